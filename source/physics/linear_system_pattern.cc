// SPDX-License-Identifier: GPL-3.0-or-later

// The sparsity pattern of LinearSystem: that of the elements, condensed
// once, and the contact couplings added to it in the steps.

#include <deal.II/base/array_view.h>

#include <ndda/physics/linear_system.h>

#include <algorithm>
#include <iterator>
#include <optional>

namespace ndda
{
  namespace
  {
    /**
     * Make @p pattern the square pattern whose row r has the columns
     * columns[start[r]], ..., columns[start[r + 1] - 1] (sorted, without
     * repeats) and the diagonal: the pattern SparsityPattern::copy_from()
     * makes of a DynamicSparsityPattern with these rows (the diagonal
     * first, then the others in order).
     */
    void
    copy_rows(const std::vector<std::size_t>             &start,
              const std::vector<types::global_dof_index> &columns,
              SparsityPattern                            &pattern)
    {
      const std::size_t n = start.size() - 1;
      std::vector<ArrayView<const types::global_dof_index>> rows;
      rows.reserve(n);
      for (std::size_t r = 0; r < n; ++r)
        rows.emplace_back(columns.data() + start[r], start[r + 1] - start[r]);
      pattern.copy_from(n, n, rows.begin(), rows.end());
    }
  } // namespace



  void
  LinearSystem::reinit(DynamicSparsityPattern &element_couplings,
                       const Constraints      &constraints,
                       const bool              with_contacts,
                       const bool              compact)
  {
    this->compact = compact;
    constraints.affine_constraints().condense(element_couplings);
    sparsity_pattern.copy_from(element_couplings);
    // The couplings of the contacts are added to this in the steps.
    if (with_contacts)
      element_sparsity.copy_from(sparsity_pattern);

    else
      element_sparsity.reinit(0, 0, 0);
    reinit_matrices(constraints);
    pattern_couplings.clear();
  }



  void
  LinearSystem::reinit_matrices(const Constraints &constraints)
  {
    assembled = false;
    stiffness_matrix.reinit(sparsity_pattern);
    mass_matrix.reinit(sparsity_pattern);
    // The damping matrix only once a cell has viscosity (add_cell_rows()):
    // most scenes have none, and it would be one more matrix with the
    // whole pattern.
    damping_matrix.clear();
    damped = false;
    if (keep_system_matrix)
      system_matrix.reinit(sparsity_pattern);
    else
      system_matrix.clear();
    condensed_base.reinit(sparsity_pattern);
    // The condensed matrix with the springs comes with the first solve
    // that has springs (solve()); a compact system solves with
    // compact_matrix instead (solver_matrix()).
    condensed_matrix.clear();
    if (!compact)
      return;
    // The pattern of the unconstrained dofs among themselves.
    const auto &affine = constraints.affine_constraints();
    const auto  n      = sparsity_pattern.n_rows();
    free_dofs.clear();
    compact_index.assign(n, numbers::invalid_dof_index);
    for (types::global_dof_index i = 0; i < n; ++i)
      if (!affine.is_constrained(i))
        {
          compact_index[i] = free_dofs.size();
          free_dofs.push_back(i);
        }
    std::vector<std::size_t>             start(1, 0);
    std::vector<types::global_dof_index> columns;
    start.reserve(free_dofs.size() + 1);
    for (const auto i : free_dofs)
      {
        const auto row_begin = columns.size();
        for (auto entry = sparsity_pattern.begin(i);
             entry != sparsity_pattern.end(i);
             ++entry)
          if (const auto c = compact_index[entry->column()];
              c != numbers::invalid_dof_index)
            columns.push_back(c);
        // The diagonal came first.
        std::sort(columns.begin() + row_begin, columns.end());
        start.push_back(columns.size());
      }
    copy_rows(start, columns, compact_pattern);
    compact_base.reinit(compact_pattern);
    compact_matrix.reinit(compact_pattern);
    // A plan on no dofs is made anew by the next block under its number
    // (add_to_compact()); its arrays are kept for that.
    for (auto &plan : compact_plans)
      {
        plan.dofs.clear();
        plan.m         = 0;
        plan.has_block = false;
      }
    setup_expansion(affine);
  }



  void
  LinearSystem::setup_expansion(const AffineConstraints<double> &affine)
  {
    const auto n = compact_index.size();
    expansion_start.assign(n + 1, 0);
    expansion_column.clear();
    expansion_weight.clear();
    for (types::global_dof_index i = 0; i < n; ++i)
      {
        if (compact_index[i] != numbers::invalid_dof_index)
          {
            expansion_column.push_back(compact_index[i]);
            expansion_weight.push_back(1.);
          }
        else if (const auto *line = affine.get_constraint_entries(i))
          for (const auto &[master, weight] : *line)
            {
              // The lines are closed: their masters are free.
              Assert(compact_index[master] != numbers::invalid_dof_index,
                     ExcInternalError());
              expansion_column.push_back(compact_index[master]);
              expansion_weight.push_back(weight);
            }
        expansion_start[i + 1] = expansion_column.size();
      }
    scratch.slot.assign(free_dofs.size(), numbers::invalid_unsigned_int);
  }



  bool
  LinearSystem::update_contact_couplings(
    const std::vector<std::pair<unsigned int, unsigned int>> &couplings,
    const DofMap                                             &dof_map,
    const Constraints                                        &constraints)
  {
    if (std::includes(pattern_couplings.begin(),
                      pattern_couplings.end(),
                      couplings.begin(),
                      couplings.end()) &&
        pattern_couplings.size() <= 2 * couplings.size() + 16)
      return false;
    std::vector<std::pair<unsigned int, unsigned int>> merged;
    std::set_union(pattern_couplings.begin(),
                   pattern_couplings.end(),
                   couplings.begin(),
                   couplings.end(),
                   std::back_inserter(merged));
    if (merged.size() > 2 * couplings.size() + 16)
      merged = couplings;
    std::optional<SectionTimer::Scope> section;
    if (timer != nullptr)
      section.emplace(*timer, "sparsity");

    // The pattern is the condensed one of the elements and the couplings
    // together. AffineConstraints::condense() maps each entry (i, j) on
    // its own: it keeps it, and adds (i, m) for the masters m of a
    // constrained j, (m, j) for those of a constrained i, (m, n) where
    // both are; the masters are free, so what it adds adds nothing more.
    // The elements' part was condensed once (reinit()): the couplings'
    // entries are condensed here alone and merged into it, row by row.
    const auto             n = element_sparsity.n_rows();
    DynamicSparsityPattern couplings_dsp(n);
    for (const auto &[vertex, cell] : merged)
      for (const auto i : dof_map.vertex_dofs[vertex])
        for (unsigned int k = 0; k < dof_map.dofs_per_cell; ++k)
          {
            const auto j = dof_map.dofs_of_cell(cell)[k];
            couplings_dsp.add(i, j);
            couplings_dsp.add(j, i);
          }
    constraints.affine_constraints().condense(couplings_dsp);

    std::vector<std::size_t>             start(n + 1, 0);
    std::vector<types::global_dof_index> columns;
    columns.reserve(element_sparsity.n_nonzero_elements() +
                    couplings_dsp.n_nonzero_elements());
    for (types::global_dof_index r = 0; r < n; ++r)
      {
        // The elements' diagonal comes first in a row (copy_rows() adds
        // it), then the others in order; the couplings' are in order.
        auto       element = std::next(element_sparsity.begin(r));
        const auto end     = element_sparsity.end(r);
        for (auto coupling = couplings_dsp.begin(r);
             coupling != couplings_dsp.end(r);
             ++coupling)
          {
            const auto c = coupling->column();
            for (; element != end && element->column() < c; ++element)
              columns.push_back(element->column());
            if (element != end && element->column() == c)
              ++element;
            if (c != r)
              columns.push_back(c);
          }
        for (; element != end; ++element)
          columns.push_back(element->column());
        start[r + 1] = columns.size();
      }
    copy_rows(start, columns, sparsity_pattern);
    reinit_matrices(constraints);
    pattern_couplings.swap(merged);
    return true;
  }
} // namespace ndda
