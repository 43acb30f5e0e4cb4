// SPDX-License-Identifier: GPL-3.0-or-later

#include <deal.II/lac/precondition.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>

#include <ndda/physics/block_rotation.h>
#include <ndda/physics/linear_system.h>

#include <algorithm>
#include <iterator>
#include <optional>

namespace ndda
{
  namespace
  {
    /** A timer section, if there is a timer. */
    std::optional<SectionTimer::Scope>
    scope(SectionTimer *timer, const char *section)
    {
      if (timer == nullptr)
        return std::nullopt;
      return std::optional<SectionTimer::Scope>(std::in_place, *timer, section);
    }

  } // namespace



  void
  LinearSystem::initialize(const parameters::LinearSolverType type,
                           const double                       tolerance,
                           SectionTimer                      *timer,
                           const MPI_Comm                     communicator)
  {
    this->timer = timer;
    linear_solver =
      std::make_unique<LinearSolver>(type, tolerance, communicator);
  }



  void
  LinearSystem::reinit(DynamicSparsityPattern &element_couplings,
                       const Constraints      &constraints,
                       const bool              with_contacts,
                       const bool              compact)
  {
    this->compact       = compact;
    this->with_contacts = with_contacts;
    element_sparsity.reinit(0, 0, 0);
    if (with_contacts && !compact)
      element_sparsity.copy_from(element_couplings);
    reinit_matrices(element_couplings, constraints);
    pattern_couplings.clear();
  }



  void
  LinearSystem::reinit_matrices(DynamicSparsityPattern &dsp,
                                const Constraints      &constraints)
  {
    constraints.affine_constraints().condense(dsp);
    sparsity_pattern.copy_from(dsp);
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
    free_dofs.clear();
    compact_index.assign(dsp.n_rows(), numbers::invalid_dof_index);
    for (types::global_dof_index i = 0; i < dsp.n_rows(); ++i)
      if (!affine.is_constrained(i))
        {
          compact_index[i] = free_dofs.size();
          free_dofs.push_back(i);
        }
    DynamicSparsityPattern               compact_dsp(free_dofs.size());
    std::vector<types::global_dof_index> row;
    for (unsigned int r = 0; r < free_dofs.size(); ++r)
      {
        row.clear();
        for (auto entry = sparsity_pattern.begin(free_dofs[r]);
             entry != sparsity_pattern.end(free_dofs[r]);
             ++entry)
          if (compact_index[entry->column()] != numbers::invalid_dof_index)
            row.push_back(compact_index[entry->column()]);
        std::sort(row.begin(), row.end());
        compact_dsp.add_entries(r, row.begin(), row.end(), true);
      }
    compact_pattern.copy_from(compact_dsp);
    if (with_contacts)
      compact_element_pattern.copy_from(compact_pattern);
    compact_base.reinit(compact_pattern);
    compact_matrix.reinit(compact_pattern);
    compact_plans.clear();
    setup_expansion(affine);
  }



  const SparseMatrix<double> &
  LinearSystem::solver_matrix()
  {
    if (compact)
      return with_springs ? compact_matrix : compact_base;
    return with_springs ? condensed_matrix : condensed_base;
  }



  unsigned int
  LinearSystem::compact_solve(const Vector<double> &b,
                              Vector<double>       &d,
                              const bool            factorize,
                              const unsigned int    gmres_iterations)
  {
    const auto run = [&](const Vector<double> &rhs, Vector<double> &x) {
      if (factorize)
        {
          {
            const auto section = scope(timer, "factorize");
            linear_solver->factorize(solver_matrix());
          }
          return linear_solver->solve(x, rhs);
        }
      if (gmres_iterations > 0)
        return linear_solver->solve_with_earlier_factorization(
          solver_matrix(), x, rhs, gmres_iterations, 1e-12);
      return linear_solver->solve(x, rhs);
    };
    if (!compact)
      return run(b, d);
    if (free_dofs.empty())
      {
        // Every dof is constrained (reduced blocks fully prescribed).
        d.reinit(b.size());
        return 1;
      }
    compact_b.reinit(free_dofs.size(), true);
    compact_d.reinit(free_dofs.size());
    for (unsigned int r = 0; r < free_dofs.size(); ++r)
      compact_b[r] = b[free_dofs[r]];
    const unsigned int iterations = run(compact_b, compact_d);
    d.reinit(b.size());
    for (unsigned int r = 0; r < free_dofs.size(); ++r)
      d[free_dofs[r]] = compact_d[r];
    return iterations;
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
    const bool shrink = merged.size() > 2 * couplings.size() + 16;
    if (shrink)
      merged = couplings;
    const auto section = scope(timer, "sparsity");
    if (compact)
      {
        // New couplings between blocks already coupled (another vertex,
        // another cell of a reduced block) expand to entries the compact
        // pattern has: it stays as it is, and with it the matrices, the
        // plans' entries and the solver's analysis.
        if (shrink || !compact_pattern_holds(couplings, dof_map))
          update_compact_couplings(merged, dof_map);
        pattern_couplings.swap(merged);
        return false;
      }
    DynamicSparsityPattern               dsp(element_sparsity.n_rows());
    std::vector<types::global_dof_index> row;
    for (types::global_dof_index i = 0; i < element_sparsity.n_rows(); ++i)
      {
        row.clear();
        for (auto entry = element_sparsity.begin(i);
             entry != element_sparsity.end(i);
             ++entry)
          row.push_back(entry->column());
        dsp.add_entries(i, row.begin(), row.end());
      }
    for (const auto &[vertex, cell] : merged)
      for (const auto i : dof_map.vertex_dofs[vertex])
        for (unsigned int k = 0; k < dof_map.dofs_per_cell; ++k)
          {
            const auto j = dof_map.dofs_of_cell(cell)[k];
            dsp.add(i, j);
            dsp.add(j, i);
          }
    reinit_matrices(dsp, constraints);
    pattern_couplings.swap(merged);
    return true;
  }



  void
  LinearSystem::prepare_step(const double       dt,
                             const double       mass_coefficient,
                             const double       damping_coefficient,
                             const Constraints &constraints,
                             const double       penalty_stiffness)
  {
    // The coefficients can change without the step: generalized-alpha's
    // first step has a mass coefficient of its own.
    if (!matrices_changed && dt == assembled_dt &&
        mass_coefficient == assembled_coefficients[0] &&
        damping_coefficient == assembled_coefficients[1])
      return;
    const auto section = scope(timer, "system matrix");
    // Condensed once: the contact springs of the steps are added to a copy
    // through the lines (solve()).
    if (keep_system_matrix)
      {
        build_system_matrix(system_matrix,
                            mass_coefficient,
                            damping_coefficient,
                            constraints,
                            penalty_stiffness);
        condensed_base.copy_from(system_matrix);
      }
    else
      build_system_matrix(condensed_base,
                          mass_coefficient,
                          damping_coefficient,
                          constraints,
                          penalty_stiffness);
    constraints.affine_constraints().condense(condensed_base);
    if (compact)
      fill_compact_base();
    assembled_dt              = dt;
    assembled_coefficients[0] = mass_coefficient;
    assembled_coefficients[1] = damping_coefficient;
    matrices_changed          = false;
    base_factorized           = false;
    ++base_version;
  }



  void
  LinearSystem::build_system_matrix(SparseMatrix<double> &matrix,
                                    const double          mass_coefficient,
                                    const double          damping_coefficient,
                                    const Constraints    &constraints,
                                    const double penalty_stiffness) const
  {
    matrix.copy_from(stiffness_matrix);
    if (mass_coefficient != 0.)
      matrix.add(mass_coefficient, mass_matrix);
    if (damped)
      matrix.add(damping_coefficient, damping_matrix);
    if (!constraints.exact())
      constraints.add_penalty_springs(penalty_stiffness, matrix);
  }



  unsigned int
  LinearSystem::solve(const SpringAssembler &add_springs,
                      Vector<double>        &b,
                      const Vector<double>  &prescribed,
                      const Constraints     &constraints,
                      const unsigned int     reuse_iterations,
                      Vector<double>        &d)
  {
    const bool springs = static_cast<bool>(add_springs);
    // The condensed matrix is the condensed system matrix with the
    // springs, unless the factorization of the one without springs serves.
    const bool  changed  = springs || !base_factorized;
    const bool  in_frame = frames != nullptr && frames->turned();
    const auto &affine   = constraints.affine_constraints();
    // The prescribed increments g (exact constraints) in the frames, and
    // A g with the springs S g, to take from b.
    if (in_frame)
      {
        prescribed_in_frame = prescribed;
        frames->to_frame(prescribed_in_frame);
      }
    const Vector<double> &g = in_frame ? prescribed_in_frame : prescribed;
    // (A fixed support prescribes zeros: nothing to take.)
    const bool with_g = constraints.exact() &&
                        !constraints.constrained_nodes().empty() &&
                        !g.all_zero();
    constraint_work = 0;
    g_blocks.clear();
    if (with_g)
      {
        // The first solve with prescribed increments: from now on the
        // system matrix is kept (prepare_step()). Exact constraints have
        // no penalty springs.
        if (!keep_system_matrix)
          {
            keep_system_matrix = true;
            system_matrix.reinit(sparsity_pattern);
            build_system_matrix(system_matrix,
                                assembled_coefficients[0],
                                assembled_coefficients[1],
                                constraints,
                                0.);
          }
        ag.reinit(b.size());
        system_matrix.vmult(ag, g);
      }
    with_springs = springs;
    if (springs)
      {
        const auto section = scope(timer, "contact assembly");
        if (compact)
          compact_matrix.copy_from(compact_base);
        else
          {
            if (condensed_matrix.empty())
              condensed_matrix.reinit(sparsity_pattern);
            condensed_matrix.copy_from(condensed_base);
          }
        add_springs(
          [&](const unsigned int                              key,
              const ArrayView<const types::global_dof_index> &dofs,
              const FullMatrix<double>                       *block) {
            // Only blocks on dofs with prescribed increments add to A g
            // (the others would add zeros).
            const bool touches_g =
              with_g && std::any_of(dofs.begin(), dofs.end(), [&](auto i) {
                return g[i] != 0.;
              });
            // The compact system keeps T^T k T of each block (see
            // add_to_compact()); else the block given is kept under its
            // key, and a null block is the one kept, if it was on the same
            // dofs.
            const bool                keep = !compact || touches_g;
            const FullMatrix<double> *k    = block;
            if (keep)
              {
                if (key >= kept_blocks.size())
                  kept_blocks.resize(key + 1);
                KeptBlock &kept = kept_blocks[key];
                if (block == nullptr)
                  {
                    if (kept.dofs.size() != dofs.size() ||
                        !std::equal(dofs.begin(),
                                    dofs.end(),
                                    kept.dofs.begin()))
                      return false;
                  }
                else
                  {
                    // Copied entry by entry: a FullMatrix assignment
                    // allocates anew.
                    const unsigned int n = dofs.size();
                    kept.dofs.assign(dofs.begin(), dofs.end());
                    if (kept.k.m() != n || kept.k.n() != n)
                      kept.k.reinit(n, n);
                    for (unsigned int i = 0; i < n; ++i)
                      for (unsigned int j = 0; j < n; ++j)
                        kept.k(i, j) = (*block)(i, j);
                  }
                k = &kept.k;
              }
            // Through the lines where a dof has one (deal.II's sorting
            // costs more than the add), else added row by row.
            if (compact)
              {
                if (!add_to_compact(key, dofs, k))
                  return false;
              }
            else if (std::any_of(dofs.begin(), dofs.end(), [&](const auto i) {
                       return affine.is_constrained(i);
                     }))
              affine.distribute_local_to_global(
                *k,
                std::vector<types::global_dof_index>(dofs.begin(), dofs.end()),
                condensed_matrix);
            else
              for (unsigned int i = 0; i < dofs.size(); ++i)
                condensed_matrix.add(
                  dofs[i], dofs.size(), dofs.data(), &(*k)(i, 0), false, false);
            if (touches_g)
              g_blocks.push_back(key);
            if (touches_g)
              for (unsigned int i = 0; i < dofs.size(); ++i)
                for (unsigned int j = 0; j < dofs.size(); ++j)
                  ag[dofs[i]] += (*k)(i, j) * g[dofs[j]];
            return true;
          },
          b);
      }
    if (in_frame)
      frames->to_frame(b);

    const auto section = scope(timer, "linear solve");
    // d = d_h + d_g: d_g carries the prescribed values, d_h satisfies the
    // homogeneous lines (of the exact constraints, and of the reduced
    // blocks with either method).
    if (with_g)
      {
        g_rows.clear();
        for (unsigned int i = 0; i < g.size(); ++i)
          if (g[i] != 0.)
            g_rows.emplace_back(i, b[i]);
        b -= ag;
      }
    affine.condense(b);
    const unsigned int iterations =
      changed ? solve_changed(b, d, springs, reuse_iterations) :
                compact_solve(b, d, false, 0);
    affine.distribute(d);
    if (constraints.exact())
      d += g;
    if (with_g)
      constraint_work = prescribed_work(g, d);
    if (in_frame)
      frames->to_global(d);
    return iterations;
  }



  double
  LinearSystem::prescribed_work(const Vector<double> &g,
                                const Vector<double> &d)
  {
    // The reactions A d - b on the rows that g moves (everything here in
    // the frames of the solve): the system matrix's rows, and the rows of
    // the contact springs on those dofs, which solve() kept.
    double work = 0;
    for (const auto &[row, b_row] : g_rows)
      {
        double reaction = -b_row;
        for (auto entry = system_matrix.begin(row);
             entry != system_matrix.end(row);
             ++entry)
          reaction += entry->value() * d[entry->column()];
        work += g[row] * reaction;
      }
    for (const unsigned int key : g_blocks)
      {
        const KeptBlock &kept = kept_blocks[key];
        for (unsigned int i = 0; i < kept.dofs.size(); ++i)
          if (g[kept.dofs[i]] != 0.)
            for (unsigned int j = 0; j < kept.dofs.size(); ++j)
              work += g[kept.dofs[i]] * kept.k(i, j) * d[kept.dofs[j]];
      }
    return work;
  }



  unsigned int
  LinearSystem::solve_changed(const Vector<double> &b,
                              Vector<double>       &d,
                              const bool            springs,
                              const unsigned int    reuse_iterations)
  {
    // Only contact springs or the contact geometry differ from the last
    // factorized system: try its factorization as GMRES preconditioner
    // first, factorize if it does not serve.
    unsigned int iterations = reuse_iterations > 0 && !refactorize_next ?
                                compact_solve(b, d, false, reuse_iterations) :
                                0;
    refactorize_next        = false;
    if (iterations == 0)
      {
        base_factorized     = !springs;
        reuse_spent         = 0;
        reuse_fewest        = numbers::invalid_unsigned_int;
        reused_base_version = numbers::invalid_unsigned_int;
        iterations          = compact_solve(b, d, true, 0);
      }
    else
      {
        // The factorization has aged when one solve converges slowly, or
        // when the iterations spent with it beyond what a new factorization
        // would have brought them back to have come to what a new one
        // costs: reuse then costs at most about twice what the best choice
        // of factorizations would have (the ski-rental argument).
        // - A system without springs whose matrix has not changed since
        //   the last such solve: one back-substitution. A factorization of
        //   it made then would have served this solve, and would serve
        //   every later one until the matrix or the springs change (the
        //   contacts of a scene that have all opened).
        // - Else the fewest iterations a solve with the present
        //   factorization took: a system that changes by as much in every
        //   step (a turning block whose matrices are rebuilt, the springs
        //   of the contacts) keeps its factorization.
        reuse_fewest         = std::min(reuse_fewest, iterations);
        const bool same_base = !springs && reused_base_version == base_version;
        reuse_spent += iterations - (same_base ? 1u : reuse_fewest);
        if (!springs)
          reused_base_version = base_version;
        if (2 * iterations > linear_solver->reuse_limit(reuse_iterations) ||
            reuse_spent > linear_solver->solves_per_factorization())
          refactorize_next = true;
      }
    return iterations;
  }



  void
  LinearSystem::solve_mass(Vector<double>     rhs,
                           const Constraints &constraints,
                           Vector<double>    &acceleration) const
  {
    SparseMatrix<double> m(sparsity_pattern);
    m.copy_from(mass_matrix);
    const auto &affine = constraints.affine_constraints();
    if (!constraints.exact())
      for (const auto &nc : constraints.constrained_nodes())
        for (const auto dof : nc.dofs)
          {
            // A reduced block's node follows its block.
            if (constraints.in_reduced_block(dof))
              continue;
            rhs[dof] = 0;
            for (auto entry = m.begin(dof); entry != m.end(dof); ++entry)
              entry->value() = (entry->column() == dof ? 1. : 0.);
          }
    affine.condense(m);
    affine.condense(rhs);
    // The consistent mass matrix is well conditioned (its condition number
    // does not grow with refinement): Jacobi-preconditioned CG needs a few
    // dozen iterations, far less than a factorization.
    acceleration.reinit(rhs.size());
    if (rhs.l2_norm() > 0)
      {
        SolverControl            control(1000, 1e-14 * rhs.l2_norm());
        SolverCG<Vector<double>> cg(control);
        PreconditionJacobi<SparseMatrix<double>> jacobi;
        jacobi.initialize(m);
        cg.solve(m, acceleration, rhs, jacobi);
      }
    affine.distribute(acceleration);
  }



  Vector<double>
  LinearSystem::lumped_mass() const
  {
    Vector<double> m(mass_matrix.m());
    for (unsigned int i = 0; i < m.size(); ++i)
      for (auto entry = mass_matrix.begin(i); entry != mass_matrix.end(i);
           ++entry)
        m[i] += entry->value();
    return m;
  }



  Vector<double>
  LinearSystem::lumped_acceleration(const Vector<double> &inertia_force) const
  {
    const Vector<double> mass = lumped_mass();
    Vector<double>       a(inertia_force);
    for (unsigned int i = 0; i < a.size(); ++i)
      if (mass[i] > 0.)
        a[i] /= mass[i];
    return a;
  }



  Vector<double>
  LinearSystem::lumped_inertia_force(const Vector<double> &a) const
  {
    Vector<double> force = lumped_mass();
    force.scale(a);
    return force;
  }



  void
  LinearSystem::invalidate()
  {
    assembled_dt     = -1;
    base_factorized  = false;
    refactorize_next = false;
  }



  void
  LinearSystem::drop_factorization()
  {
    invalidate();
    reuse_spent         = 0;
    reuse_fewest        = numbers::invalid_unsigned_int;
    reused_base_version = numbers::invalid_unsigned_int;
    if (linear_solver)
      linear_solver->forget_factorization();
  }
} // namespace ndda
