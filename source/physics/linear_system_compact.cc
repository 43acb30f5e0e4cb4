// SPDX-License-Identifier: GPL-3.0-or-later

// The compact system of LinearSystem: the unconstrained dofs alone, with
// the contact couplings and springs expanded through the lines of the
// reduced blocks.

#include <ndda/physics/linear_system.h>

#include <algorithm>

namespace ndda
{
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



  void
  LinearSystem::make_compact_plan(
    const ArrayView<const types::global_dof_index> &dofs,
    CompactPlan                                    &plan)
  {
    // The compact unknowns the block touches (sorted), and T (n x m) in
    // sparse rows: a dof expands to one to a few compact unknowns.
    const unsigned int n = dofs.size();
    plan.dofs.assign(dofs.begin(), dofs.end());
    plan.has_block = false;
    auto &columns  = scratch.columns;
    auto &slot     = scratch.slot;
    columns.clear();
    for (const auto i : dofs)
      for (auto e = expansion_start[i]; e < expansion_start[i + 1]; ++e)
        if (slot[expansion_column[e]] == numbers::invalid_unsigned_int)
          {
            slot[expansion_column[e]] = columns.size();
            columns.push_back(expansion_column[e]);
          }
    const unsigned int m = columns.size();
    plan.m               = m;
    std::sort(columns.begin(), columns.end());
    for (unsigned int a = 0; a < m; ++a)
      slot[columns[a]] = a;
    plan.row_start.assign(1, 0);
    plan.position.clear();
    plan.weight.clear();
    for (unsigned int i = 0; i < n; ++i)
      {
        for (auto e = expansion_start[dofs[i]];
             e < expansion_start[dofs[i] + 1];
             ++e)
          {
            plan.position.push_back(slot[expansion_column[e]]);
            plan.weight.push_back(expansion_weight[e]);
          }
        plan.row_start.push_back(plan.position.size());
      }
    for (const auto c : columns)
      slot[c] = numbers::invalid_unsigned_int;
    plan.columns.assign(columns.begin(), columns.end());
    locate_compact_entries(plan);
  }



  void
  LinearSystem::locate_compact_entries(CompactPlan &plan) const
  {
    // Where the m x m entries are among the compact matrix's values (the
    // contact couplings are in its pattern: a missing one is an error).
    const unsigned int m = plan.m;
    plan.entries.resize(m * m);
    for (unsigned int a = 0; a < m; ++a)
      for (unsigned int b = 0; b < m; ++b)
        {
          const auto entry = compact_pattern(plan.columns[a], plan.columns[b]);
          Assert(entry != SparsityPattern::invalid_entry, ExcInternalError());
          plan.entries[a * m + b] = entry;
        }
    plan.pattern_version = compact_pattern_version;
  }



  bool
  LinearSystem::add_to_compact(
    const unsigned int                              key,
    const ArrayView<const types::global_dof_index> &dofs,
    const FullMatrix<double>                       *k)
  {
    // The blocks are small (6 x 6 to 14 x 14): plain loops, no allocation
    // once the plans are made.
    if (key >= compact_plans.size())
      compact_plans.resize(key + 1);
    CompactPlan       &plan = compact_plans[key];
    const unsigned int n    = dofs.size();
    if (plan.dofs.size() != n ||
        !std::equal(dofs.begin(), dofs.end(), plan.dofs.begin()))
      {
        if (k == nullptr)
          return false;
        make_compact_plan(dofs, plan);
      }
    else if (plan.pattern_version != compact_pattern_version)
      locate_compact_entries(plan);
    if (k == nullptr && !plan.has_block)
      return false;
    const unsigned int m = plan.m;
    if (m == 0)
      return true;
    // The values of a SparseMatrix are one array in the order of its
    // pattern's entries; the diagonal of row 0 is its first.
    Assert(compact_pattern(0, 0) == 0, ExcInternalError());
    double *const values = &compact_matrix.diag_element(0);
    auto         &tkt    = plan.block;
    if (k != nullptr)
      {
        const auto &start    = plan.row_start;
        const auto &position = plan.position;
        const auto &weight   = plan.weight;
        // k t (n x m), then t^T k t (m x m).
        auto &kt = scratch.kt;
        kt.assign(n * m, 0.);
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int l = 0; l < n; ++l)
            if (const double kil = (*k)(i, l); kil != 0.)
              for (unsigned int q = start[l]; q < start[l + 1]; ++q)
                kt[i * m + position[q]] += kil * weight[q];
        tkt.assign(m * m, 0.);
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int q = start[i]; q < start[i + 1]; ++q)
            {
              const double w   = weight[q];
              double      *row = &tkt[position[q] * m];
              for (unsigned int b = 0; b < m; ++b)
                row[b] += w * kt[i * m + b];
            }
        plan.has_block = true;
      }
    for (unsigned int e = 0; e < m * m; ++e)
      values[plan.entries[e]] += tkt[e];
    return true;
  }


  void
  LinearSystem::expand_in_compact(
    const ArrayView<const types::global_dof_index> &dofs,
    std::vector<types::global_dof_index>           &columns) const
  {
    columns.clear();
    for (const auto i : dofs)
      for (auto e = expansion_start[i]; e < expansion_start[i + 1]; ++e)
        columns.push_back(expansion_column[e]);
    std::sort(columns.begin(), columns.end());
    columns.erase(std::unique(columns.begin(), columns.end()), columns.end());
  }



  bool
  LinearSystem::compact_pattern_holds(
    const std::vector<std::pair<unsigned int, unsigned int>> &couplings,
    const DofMap                                             &dof_map) const
  {
    // Those not in the pattern's couplings (both lists sorted); the
    // compact pattern is symmetric, so one of (a, b) and (b, a) tells.
    std::vector<std::pair<unsigned int, unsigned int>> added;
    std::set_difference(couplings.begin(),
                        couplings.end(),
                        pattern_couplings.begin(),
                        pattern_couplings.end(),
                        std::back_inserter(added));
    std::vector<types::global_dof_index> vertex_columns, cell_columns;
    auto last_vertex = numbers::invalid_unsigned_int;
    for (const auto &[vertex, cell] : added)
      {
        if (vertex != last_vertex)
          {
            expand_in_compact(dof_map.vertex_dofs[vertex], vertex_columns);
            last_vertex = vertex;
          }
        expand_in_compact(ArrayView<const types::global_dof_index>(
                            dof_map.dofs_of_cell(cell), dof_map.dofs_per_cell),
                          cell_columns);
        for (const auto a : vertex_columns)
          for (const auto b : cell_columns)
            if (!compact_pattern.exists(a, b))
              return false;
      }
    return true;
  }



  void
  LinearSystem::update_compact_couplings(
    const std::vector<std::pair<unsigned int, unsigned int>> &couplings,
    const DofMap                                             &dof_map)
  {
    // Condensing an entry (i, j) of the whole pattern gives the entries
    // (a, b), a in the expansion of i and b in that of j, among the free
    // dofs (the lines are closed); the compact pattern is those of the
    // elements' entries, kept, and of the couplings' entries.
    const auto                           n_free = free_dofs.size();
    DynamicSparsityPattern               dsp(n_free);
    std::vector<types::global_dof_index> row, vertex_columns, cell_columns;
    for (types::global_dof_index r = 0; r < n_free; ++r)
      {
        row.clear();
        for (auto entry = compact_element_pattern.begin(r);
             entry != compact_element_pattern.end(r);
             ++entry)
          row.push_back(entry->column());
        std::sort(row.begin(), row.end());
        dsp.add_entries(r, row.begin(), row.end(), true);
      }
    // The couplings come sorted by vertex: a vertex is expanded once, and
    // a cell whose expansion is that of the cell before (a rigid or
    // affine block's cells) adds nothing new.
    std::vector<types::global_dof_index> last_cell_columns;
    auto last_vertex = numbers::invalid_unsigned_int;
    for (const auto &[vertex, cell] : couplings)
      {
        if (vertex != last_vertex)
          {
            expand_in_compact(dof_map.vertex_dofs[vertex], vertex_columns);
            last_vertex = vertex;
            last_cell_columns.clear();
          }
        expand_in_compact(ArrayView<const types::global_dof_index>(
                            dof_map.dofs_of_cell(cell), dof_map.dofs_per_cell),
                          cell_columns);
        if (cell_columns == last_cell_columns)
          continue;
        for (const auto a : vertex_columns)
          dsp.add_entries(a, cell_columns.begin(), cell_columns.end(), true);
        for (const auto b : cell_columns)
          dsp.add_entries(b,
                          vertex_columns.begin(),
                          vertex_columns.end(),
                          true);
        last_cell_columns.swap(cell_columns);
      }
    compact_pattern.copy_from(dsp);
    compact_base.reinit(compact_pattern);
    compact_matrix.reinit(compact_pattern);
    // The plans keep their expansions and blocks, and find their entries
    // anew when next used (add_to_compact()).
    ++compact_pattern_version;
    // The base matrix's values are those of before, on a larger pattern:
    // a new matrix for the solver, as a rebuilt one would be.
    if (!matrices_changed)
      fill_compact_base();
    base_factorized = false;
    ++base_version;
  }



  void
  LinearSystem::fill_compact_base()
  {
    const SparseMatrix<double> &condensed = condensed_base;
    for (unsigned int r = 0; r < free_dofs.size(); ++r)
      {
        auto target = compact_base.begin(r);
        for (auto entry = condensed.begin(free_dofs[r]);
             entry != condensed.end(free_dofs[r]);
             ++entry)
          {
            const auto c = compact_index[entry->column()];
            if (c == numbers::invalid_dof_index)
              continue;
            // Both rows list their columns in the same order, the
            // diagonal first; the compact row may have more.
            while (target->column() != c)
              ++target;
            target->value() = entry->value();
          }
      }
  }

} // namespace ndda
