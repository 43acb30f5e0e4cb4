// SPDX-License-Identifier: GPL-3.0-or-later

/**
 * @file
 * The first stage of ndda on several MPI processes (issue 19): the linear
 * solve of step_vs_plain_solve's system by DistributedSolver.
 *
 * Run as `mpirun -np P distributed_solve 1e5 1e6` (as root with
 * --allow-run-as-root). For every target size, ndda only meshes the scene
 * of step_vs_plain_solve (plain_system.h; setup(), no step), and every
 * process assembles and solves the same plain system of its first Newmark
 * step (SparseDirectUMFPACK, the reference solution). Then three solvers
 * solve it, each timed between barriers: ndda's serial direct solver
 * (`direct`: CHOLMOD, on every process alike; the baseline, as the
 * "matched" columns of step_vs_plain_solve), and DistributedSolver on the
 * P processes with MUMPS (symmetric positive definite) and with CG-AMG
 * (rigid-body modes, relative residual 1e-10, ndda's default Solver
 * tolerance). Timed: the first factorize() (for DistributedSolver the
 * split of the rows by METIS, the copy to Trilinos' matrix, MUMPS's
 * analysis and factorization, or ML's hierarchy), a second one on the same
 * pattern (CHOLMOD's and MUMPS's analysis kept, no METIS), the solve and a
 * second solve; and the relative l2 difference to the reference. Also
 * printed: the triangulation's memory per cell, which every process of a
 * parallel::shared::Triangulation would hold whole. Run with P = 1 and 2.
 *
 * Usage: distributed_solve [target n_dofs ...] (default 1e5)
 */

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/table_handler.h>

#include <ndda/parallel/distributed_solver.h>

#include <iostream>
#include <string>
#include <type_traits>
#include <vector>

#include "plain_system.h"

using namespace dealii;
using namespace plain_system;

namespace
{
  /** The timings of the solvers, one entry per solver. */
  struct DistributedResult
  {
    std::vector<std::string> methods;
    std::vector<double>      factorize_time, refactorize_time, solve_time,
      resolve_time, difference;
    std::vector<unsigned int> iterations;
    /// The fewest and the most rows a process owns.
    unsigned int min_rows = 0, max_rows = 0;
  };


  /** Seconds since @p start, once every process has got there. */
  double
  collective_seconds_since(const Clock::time_point start)
  {
    MPI_Barrier(MPI_COMM_WORLD);
    return seconds_since(start);
  }


  /**
   * Time two factorizations of @p matrix with @p solver (the second on the
   * same pattern), two solves of matrix x = @p rhs, and the difference to
   * the plain solution; @p Solver is ndda's LinearSolver or
   * DistributedSolver (whose factorize() takes whether the matrix is
   * SPD).
   */
  template <typename Solver>
  void
  time_solver(const std::string               &name,
              Solver                          &solver,
              const SparseMatrix<double>      &matrix,
              const Vector<double>            &rhs,
              const AffineConstraints<double> &constraints,
              const Vector<double>            &plain_solution,
              DistributedResult               &result)
  {
    result.methods.push_back(name);
    for (auto *time : {&result.factorize_time, &result.refactorize_time})
      {
        MPI_Barrier(MPI_COMM_WORLD);
        const auto start = Clock::now();
        if constexpr (std::is_same_v<Solver, ndda::LinearSolver>)
          solver.factorize(matrix);
        else
          solver.factorize(matrix, true);
        time->push_back(collective_seconds_since(start));
      }
    Vector<double> x(matrix.m());
    for (auto *time : {&result.solve_time, &result.resolve_time})
      {
        MPI_Barrier(MPI_COMM_WORLD);
        const auto         start      = Clock::now();
        const unsigned int iterations = solver.solve(x, rhs);
        constraints.distribute(x);
        time->push_back(collective_seconds_since(start));
        if (time == &result.solve_time)
          result.iterations.push_back(iterations);
      }
    x -= plain_solution;
    result.difference.push_back(x.l2_norm() / plain_solution.l2_norm());
  }


  /**
   * Solve @p matrix x = @p rhs with ndda's serial direct solver (CHOLMOD,
   * on every process alike), and with DistributedSolver on all processes
   * of MPI_COMM_WORLD, MUMPS and CG-AMG (see the file comment).
   */
  void
  distributed_solves(const DoFHandler<2>             &dof_handler,
                     const Mapping<2>                &mapping,
                     const SparseMatrix<double>      &matrix,
                     const Vector<double>            &rhs,
                     const AffineConstraints<double> &constraints,
                     const Vector<double>            &plain_solution,
                     DistributedResult               &result)
  {
    std::vector<Point<2>> location(dof_handler.n_dofs());
    DoFTools::map_dofs_to_support_points(mapping, dof_handler, location);
    std::vector<unsigned int>            component(dof_handler.n_dofs());
    std::vector<types::global_dof_index> dofs(
      dof_handler.get_fe().n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < dofs.size(); ++i)
          component[dofs[i]] =
            dof_handler.get_fe().system_to_component_index(i).first;
      }

    {
      ndda::LinearSolver serial(ndda::parameters::LinearSolverType::direct, 0.);
      time_solver("CHOLMOD, serial",
                  serial,
                  matrix,
                  rhs,
                  constraints,
                  plain_solution,
                  result);
    }
    using Method = ndda::DistributedSolver::Method;
    for (const Method method : {Method::mumps, Method::cg_amg})
      {
        ndda::DistributedSolver solver(MPI_COMM_WORLD, method, 1e-10);
        if (method == Method::cg_amg)
          solver.set_rigid_body_modes(location, component);
        time_solver(ndda::DistributedSolver::name(method),
                    solver,
                    matrix,
                    rhs,
                    constraints,
                    plain_solution,
                    result);
        const unsigned int rows = solver.locally_owned_rows().n_elements();
        result.min_rows         = Utilities::MPI::min(rows, MPI_COMM_WORLD);
        result.max_rows         = Utilities::MPI::max(rows, MPI_COMM_WORLD);
      }
  }


  /**
   * --distributed: for every target, ndda's mesh of the scene, the plain
   * system, and DistributedSolver on all processes (see the file comment).
   */
  void
  run_distributed(const std::vector<double> &targets)
  {
    const unsigned int n_processes =
      Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
    ConditionalOStream out(std::cout,
                           Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) ==
                             0);
    TableHandler       table;
    for (const double target : targets)
      {
        Triangulation<2> triangulation;
        auto matched_type = ndda::parameters::LinearSolverType::umfpack;
        {
          ParameterHandler             prm;
          ndda::parameters::Parameters parameters;
          parameters.read(scene_text(static_cast<unsigned int>(target), ""),
                          "step_vs_plain_solve.prm",
                          prm);
          matched_type = parameters.control.linear_solver;
          ndda::Simulator<2> simulator(parameters);
          simulator.setup();
          triangulation.copy_triangulation(
            simulator.get_mesh().get_triangulation());
        }
        reset_peak_rss();
        DistributedResult distributed;
        const PlainResult plain = plain_solve(
          triangulation,
          matched_type,
          [&distributed](const DoFHandler<2>             &dof_handler,
                         const Mapping<2>                &mapping,
                         const SparseMatrix<double>      &matrix,
                         const Vector<double>            &rhs,
                         const AffineConstraints<double> &constraints,
                         const Vector<double>            &solution) {
            distributed_solves(dof_handler,
                               mapping,
                               matrix,
                               rhs,
                               constraints,
                               solution,
                               distributed);
          });
        const double peak_rss =
          Utilities::MPI::max(status_bytes("VmHWM"), MPI_COMM_WORLD);
        for (unsigned int m = 0; m < distributed.methods.size(); ++m)
          {
            table.add_value("n_dofs", plain.solution.size());
            table.add_value("processes", n_processes);
            table.add_value("rows min-max",
                            std::to_string(distributed.min_rows) + "-" +
                              std::to_string(distributed.max_rows));
            table.add_value("method", distributed.methods[m]);
            table.add_value("factorize (s)", distributed.factorize_time[m]);
            table.add_value("refactorize (s)", distributed.refactorize_time[m]);
            table.add_value("solve (s)", distributed.solve_time[m]);
            table.add_value("re-solve (s)", distributed.resolve_time[m]);
            table.add_value("iterations", distributed.iterations[m]);
            table.add_value("rel. diff", distributed.difference[m]);
            table.add_value("peak RSS/process (MB)", peak_rss / 1e6);
          }
        out << "target " << target << ": " << plain.solution.size() << " DoFs, "
            << triangulation.n_active_cells()
            << " cells; the triangulation holds "
            << triangulation.memory_consumption() /
                 triangulation.n_active_cells()
            << " bytes per cell" << std::endl;
      }
    for (const auto &column :
         {"factorize (s)", "refactorize (s)", "solve (s)", "re-solve (s)"})
      table.set_precision(column, 4);
    table.set_scientific("rel. diff", true);
    table.set_precision("rel. diff", 2);
    table.set_precision("peak RSS/process (MB)", 1);
    out << std::endl;
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      table.write_text(std::cout, TableHandler::org_mode_table);
  }
} // namespace


int
main(int argc, char **argv)
{
  try
    {
      Utilities::MPI::MPI_InitFinalize mpi(argc,
                                           argv,
                                           numbers::invalid_unsigned_int);
      std::vector<double>              targets;
      for (int a = 1; a < argc; ++a)
        targets.push_back(std::stod(argv[a]));
      if (targets.empty())
        targets = {1e5};
      run_distributed(targets);
    }
  catch (const std::exception &exc)
    {
      std::cerr << "distributed_solve: " << exc.what() << std::endl;
      return 1;
    }
  return 0;
}
