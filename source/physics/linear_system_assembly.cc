// SPDX-License-Identifier: GPL-3.0-or-later

#include <deal.II/base/parallel.h>

#include <ndda/physics/linear_system.h>

#include <algorithm>
#include <atomic>

namespace ndda
{
  namespace
  {
    /**
     * Copy the nonzero entries of row @p r of @p full into the same row of
     * @p pruned, and zero the rest of it. Both patterns list a row's
     * columns the same way (the diagonal first, then by column), so the
     * nonzero entries come in the order of the pruned row: one walk along
     * both rows. Returns false if the pruned row lacks a column of a
     * nonzero entry.
     */
    bool
    copy_nonzero_row(const SparseMatrix<double> &full,
                     SparseMatrix<double>       &pruned,
                     const unsigned int          r)
    {
      auto       target = pruned.begin(r);
      const auto last   = pruned.end(r);
      for (auto entry = full.begin(r); entry != full.end(r); ++entry)
        {
          // A double, not deal.II's reference proxy, whose assignment from
          // another proxy would copy the proxy.
          const double value = entry->value();
          if (value == 0.)
            continue;
          while (target != last && target->column() != entry->column())
            {
              target->value() = 0.;
              ++target;
            }
          if (target == last)
            return false;
          target->value() = value;
          ++target;
        }
      for (; target != last; ++target)
        target->value() = 0.;
      return true;
    }



    /** Set every entry of row @p row of @p matrix to zero. */
    void
    zero_row(SparseMatrix<double> &matrix, const types::global_dof_index row)
    {
      for (auto entry = matrix.begin(row); entry != matrix.end(row); ++entry)
        entry->value() = 0.;
    }
  } // namespace



  void
  LinearSystem::add_cell_rows(const ElementCache<2>::CellData            &data,
                              const std::vector<types::global_dof_index> &dofs,
                              const std::vector<bool>                    *rows)
  {
    // Row by row, as SparseMatrix::add(indices, full_matrix) adds a full
    // matrix: the same additions in the same order (the zeros of the mass
    // between components are not added, as add() elides zeros).
    const unsigned int n = dofs.size();
    mass_row.resize(n);
    for (unsigned int i = 0; i < n; ++i)
      {
        if (rows != nullptr && !(*rows)[dofs[i]])
          continue;
        stiffness_matrix.add(dofs[i], n, dofs.data(), &data.stiffness(i, 0));
        for (unsigned int j = 0; j < n; ++j)
          mass_row[j] = data.mass(i, j);
        mass_matrix.add(dofs[i], n, dofs.data(), mass_row.data());
        if (data.viscosity_over_density > 0)
          {
            if (damping_matrix.empty())
              damping_matrix.reinit(sparsity_pattern);
            damped = true;
            for (unsigned int j = 0; j < n; ++j)
              damping_matrix.add(dofs[i],
                                 dofs[j],
                                 data.viscosity_over_density * data.mass(i, j));
          }
      }
  }



  void
  LinearSystem::assemble(const ElementCache<2>           &element_cache,
                         const DofMap                    &dof_map,
                         const BoltSprings               &bolts,
                         const Vector<double>            &displacement,
                         const std::vector<unsigned int> *changed_cells)
  {
    matrices_changed                             = true;
    const unsigned int                   n_dofs  = dof_map.dofs_per_cell;
    const unsigned int                   n_cells = dof_map.n_cells();
    std::vector<types::global_dof_index> dofs(n_dofs);
    const auto                           dofs_of = [&](const unsigned int c) {
      std::copy(dof_map.dofs_of_cell(c),
                dof_map.dofs_of_cell(c) + n_dofs,
                dofs.begin());
    };

    // Only some cells changed since the last full assembly: the rows of
    // their dofs are summed again, from every cell on those dofs in cell
    // order, so that every entry is the same sum, added in the same order,
    // as in a full assembly (bit for bit; unit test linear_system). Bolt
    // springs are added after the cells and depend on the displacement:
    // with bolts, every row is summed again.
    if (changed_cells != nullptr && assembled && bolts.empty() &&
        2 * changed_cells->size() < n_cells)
      {
        std::vector<bool> rows(stiffness_matrix.m(), false);
        for (const unsigned int c : *changed_cells)
          for (unsigned int i = 0; i < n_dofs; ++i)
            rows[dof_map.dofs_of_cell(c)[i]] = true;
        for (types::global_dof_index r = 0; r < rows.size(); ++r)
          if (rows[r])
            {
              zero_row(stiffness_matrix, r);
              zero_row(mass_matrix, r);
              if (damped)
                zero_row(damping_matrix, r);
            }
        for (unsigned int c = 0; c < n_cells; ++c)
          {
            const auto *cell_dofs = dof_map.dofs_of_cell(c);
            if (std::none_of(cell_dofs, cell_dofs + n_dofs, [&](auto i) {
                  return static_cast<bool>(rows[i]);
                }))
              continue;
            dofs_of(c);
            add_cell_rows(element_cache[c], dofs, &rows);
          }
        // Only those rows of the mass matrix without its zeros change,
        // unless one of them gained an entry its pattern lacks.
        bool fits =
          !mass_operator.empty() && mass_operator.m() == mass_matrix.m();
        for (types::global_dof_index r = 0; fits && r < rows.size(); ++r)
          if (rows[r])
            fits = copy_nonzero_row(mass_matrix, mass_operator, r);
        if (!fits)
          prune_mass_matrix();
        return;
      }

    stiffness_matrix = 0;
    mass_matrix      = 0;
    if (!damping_matrix.empty())
      damping_matrix = 0;
    damped = false;
    for (unsigned int c = 0; c < n_cells; ++c)
      {
        dofs_of(c);
        add_cell_rows(element_cache[c], dofs, nullptr);
      }
    bolts.add_stiffness(displacement, stiffness_matrix);
    assembled = true;
    prune_mass_matrix();
  }



  void
  LinearSystem::prune_mass_matrix()
  {
    // Row by row (copy_nonzero_row()), on deal.II's threads (each row its
    // own).
    const auto copy_rows = [&](const unsigned int begin,
                               const unsigned int end) {
      for (unsigned int r = begin; r < end; ++r)
        if (!copy_nonzero_row(mass_matrix, mass_operator, r))
          return false;
      return true;
    };
    const unsigned int n = mass_matrix.m();
    if (!mass_operator.empty() && mass_operator.m() == n && n > 0)
      {
        std::atomic<bool> fits(true);
        parallel::apply_to_subranges(
          0u,
          n,
          [&](const unsigned int begin, const unsigned int end) {
            if (!copy_rows(begin, end))
              fits = false;
          },
          4096);
        if (fits)
          return;
      }
    // A pattern of the nonzero entries (and every diagonal).
    std::vector<unsigned int> row_length(n, 1);
    for (unsigned int r = 0; r < n; ++r)
      for (auto entry = mass_matrix.begin(r); entry != mass_matrix.end(r);
           ++entry)
        if (entry->value() != 0. && entry->column() != r)
          ++row_length[r];
    mass_operator.clear();
    mass_pattern.reinit(n, n, row_length);
    // The diagonal is stored first by the pattern itself; the others come
    // sorted, as in mass_matrix's row.
    std::vector<types::global_dof_index> columns;
    for (unsigned int r = 0; r < n; ++r)
      {
        columns.clear();
        for (auto entry = mass_matrix.begin(r); entry != mass_matrix.end(r);
             ++entry)
          if (entry->value() != 0. && entry->column() != r)
            columns.push_back(entry->column());
        mass_pattern.add_entries(r, columns.begin(), columns.end(), true);
      }
    mass_pattern.compress();
    mass_operator.reinit(mass_pattern);
    const bool copied = copy_rows(0, n);
    Assert(copied, ExcInternalError());
    (void)copied;
  }
} // namespace ndda
