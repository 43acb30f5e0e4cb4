// SPDX-License-Identifier: GPL-3.0-or-later
//
// DistributedSolver and OwnedCells (issue 19), run by ctest on two MPI
// processes (`mpirun -np 2`), and correct on any number of them:
//
//  1. the rows of a P1 plane-stress elasticity matrix (K + c M on a
//     triangulated 4 x 1 rectangle, boundary fixed, 7,502 dofs) are split
//     among the processes without gap or overlap, every process owning
//     some (METIS);
//  2. MUMPS with its symmetric positive definite factorization gives the
//     solution of ndda's serial direct solver (CHOLMOD) to 1e-12, for two
//     right-hand sides with one factorization, and every process gets the
//     same whole solution, bit for bit;
//  3. new values on the same pattern keep the split of the rows and are
//     solved as well, and a new pattern (one more coupling) is split and
//     factorized anew; rows owned as the caller says
//     (set_row_owners()) are split so and solved as well;
//  4. MUMPS's general LU solves a non-symmetric matrix (the elasticity
//     matrix plus a skew-symmetric part, as friction makes it) as UMFPACK
//     does, to 1e-12;
//  5. CG with ML's AMG and the rigid-body modes reaches a relative residual
//     of 1e-12 in fewer than 60 iterations and agrees with CHOLMOD to 1e-9;
//  6. OwnedCells, the split of the cells for the per-cell work: contiguous
//     ranges without gap or overlap, as equal as they can be, and share()
//     gives every process every cell's values (all cells, or a list);
//  7. SerialWork, the first process's work while the others wait: on the
//     threads and the cores of every process of its machine (mpirun binds
//     each process to a core of its own by default), back to its own
//     number of threads and its own cores after, and its error thrown on
//     every process.

#include <deal.II/base/mpi.h>
#include <deal.II/base/multithread_info.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/tensor.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_fe.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <ndda/parallel/distributed_solver.h>
#include <ndda/parallel/owned_cells.h>
#include <ndda/parallel/serial_work.h>
#include <ndda/physics/linear_solver.h>

#include <iomanip>
#include <iostream>
#include <sched.h>
#include <tbb/task_arena.h>

#include "tests.h"

using namespace dealii;
using namespace ndda;
using ndda_tests::check;

namespace
{
  /** A P1 elasticity system on a triangulated rectangle. */
  struct System
  {
    Triangulation<2>          triangulation;
    FESystem<2>               fe{FE_SimplexP<2>(1), 2};
    MappingFE<2>              mapping{FE_SimplexP<2>(1)};
    DoFHandler<2>             dof_handler;
    AffineConstraints<double> constraints;
    SparsityPattern           pattern;
    SparseMatrix<double>      matrix;
    /// Gravity, and a load pulling the right half to the right.
    Vector<double> gravity, pull;

    System()
    {
      GridGenerator::subdivided_hyper_rectangle_with_simplices(triangulation,
                                                               {120, 30},
                                                               Point<2>(0, 0),
                                                               Point<2>(4, 1));
      dof_handler.reinit(triangulation);
      dof_handler.distribute_dofs(fe);
      DoFTools::make_zero_boundary_constraints(dof_handler, 0, constraints);
      constraints.close();
      DynamicSparsityPattern dsp(dof_handler.n_dofs());
      DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
      pattern.copy_from(dsp);
      matrix.reinit(pattern);
      gravity.reinit(dof_handler.n_dofs());
      pull.reinit(dof_handler.n_dofs());
      assemble(1.);
    }

    /** K(E) + 4 / dt^2 M, dt = 1e-3, with Young's modulus E GPa. */
    void
    assemble(const double youngs_modulus_gpa)
    {
      matrix         = 0;
      gravity        = 0;
      pull           = 0;
      const double e = youngs_modulus_gpa * 1e9, nu = 0.25, rho = 2500.;
      const double mu = e / (2. * (1. + nu)), lambda = e * nu / (1. - nu * nu);
      const double c_mass = 4. / (1e-3 * 1e-3);
      const QGaussSimplex<2>               quadrature(2);
      FEValues<2>                          fe_values(mapping,
                            fe,
                            quadrature,
                            update_values | update_gradients |
                              update_JxW_values | update_quadrature_points);
      const unsigned int                   n = fe.n_dofs_per_cell();
      FullMatrix<double>                   cell_matrix(n, n);
      Vector<double>                       cell_gravity(n), cell_pull(n);
      std::vector<types::global_dof_index> dofs(n);
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          fe_values.reinit(cell);
          cell_matrix  = 0;
          cell_gravity = 0;
          cell_pull    = 0;
          for (const unsigned int q : fe_values.quadrature_point_indices())
            for (unsigned int i = 0; i < n; ++i)
              {
                const unsigned int ci = fe.system_to_component_index(i).first;
                const double       wi = fe_values.shape_value(i, q);
                const auto         gi = fe_values.shape_grad(i, q);
                for (unsigned int j = 0; j < n; ++j)
                  {
                    const unsigned int cj =
                      fe.system_to_component_index(j).first;
                    const auto gj = fe_values.shape_grad(j, q);
                    double k = lambda * gi[ci] * gj[cj] + mu * gi[cj] * gj[ci] +
                               (ci == cj ? mu * gi * gj : 0.);
                    if (ci == cj)
                      k += c_mass * rho * wi * fe_values.shape_value(j, q);
                    cell_matrix(i, j) += k * fe_values.JxW(q);
                  }
                if (ci == 1)
                  cell_gravity(i) -= rho * 9.81 * wi * fe_values.JxW(q);
                if (ci == 0 && fe_values.quadrature_point(q)[0] > 2.)
                  cell_pull(i) += 1e6 * wi * fe_values.JxW(q);
              }
          cell->get_dof_indices(dofs);
          constraints.distribute_local_to_global(
            cell_matrix, cell_gravity, dofs, matrix, gravity);
          constraints.distribute_local_to_global(cell_pull, dofs, pull);
        }
    }

    void
    rigid_body_modes(DistributedSolver &solver) const
    {
      std::vector<Point<2>> location(dof_handler.n_dofs());
      DoFTools::map_dofs_to_support_points(mapping, dof_handler, location);
      std::vector<unsigned int>            component(dof_handler.n_dofs());
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            component[dofs[i]] = fe.system_to_component_index(i).first;
        }
      solver.set_rigid_body_modes(location, component);
    }
  };


  double
  relative_difference(const Vector<double> &x, const Vector<double> &y)
  {
    Vector<double> d(x);
    d -= y;
    return d.l2_norm() / y.l2_norm();
  }


  /** The serial reference: ndda's LinearSolver of @p type. */
  Vector<double>
  serial_solution(const parameters::LinearSolverType type,
                  const SparseMatrix<double>        &matrix,
                  const Vector<double>              &b)
  {
    LinearSolver solver(type, 0.);
    solver.factorize(matrix);
    Vector<double> x(b.size());
    solver.solve(x, b);
    return x;
  }


} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                   comm = MPI_COMM_WORLD;
  const unsigned int n_processes        = Utilities::MPI::n_mpi_processes(comm);
  ConditionalOStream out(std::cout,
                         Utilities::MPI::this_mpi_process(comm) == 0);
  // The measured differences, for the log (not compared).
  ConditionalOStream diagnostics(std::cerr,
                                 Utilities::MPI::this_mpi_process(comm) == 0);
  out << "processes: " << (n_processes > 1 ? "several" : "one") << std::endl;

  System             system;
  const unsigned int n = system.dof_handler.n_dofs();
  out << "dofs: " << n << std::endl;

  // 1. The split of the rows.
  DistributedSolver mumps(comm, DistributedSolver::Method::mumps);
  mumps.factorize(system.matrix, true);
  const IndexSet owned = mumps.locally_owned_rows();
  {
    Vector<double> count(n);
    for (const auto row : owned)
      count[row] = 1.;
    Utilities::MPI::sum(count, comm, count);
    bool once = true;
    for (const double c : count)
      once = once && c == 1.;
    check(once, "every row is owned by exactly one process");
    check(Utilities::MPI::min(owned.n_elements(), comm) > 0,
          "every process owns some rows");
  }
  out << "rows split among the processes without gap or overlap" << std::endl;

  // 2. MUMPS, symmetric positive definite, two right-hand sides.
  for (const Vector<double> *b : {&system.gravity, &system.pull})
    {
      const Vector<double> reference =
        serial_solution(parameters::LinearSolverType::direct,
                        system.matrix,
                        *b);
      Vector<double> x(n);
      check(mumps.solve(x, *b) == 1, "MUMPS reports one solve");
      const double difference = relative_difference(x, reference);
      diagnostics << "MUMPS SPD against CHOLMOD: " << difference << std::endl;
      check(difference <= 1e-12, "MUMPS (SPD) agrees with CHOLMOD to 1e-12");
      check(ndda_tests::same_on_every_process(x, comm),
            "every process has the same solution");
    }
  out << "MUMPS (SPD): CHOLMOD's solution to 1e-12, two right-hand sides, "
      << "the same on every process" << std::endl;

  // 3. New values, same pattern: the split is kept.
  system.assemble(3.);
  mumps.factorize(system.matrix, true);
  check(mumps.locally_owned_rows() == owned, "the split is kept");
  {
    const Vector<double> reference =
      serial_solution(parameters::LinearSolverType::direct,
                      system.matrix,
                      system.gravity);
    Vector<double> x(n);
    mumps.solve(x, system.gravity);
    check(relative_difference(x, reference) <= 1e-12,
          "MUMPS agrees with CHOLMOD after new values");
  }
  out << "new values on the same pattern: split kept, solved to 1e-12"
      << std::endl;

  // 3b. A new pattern (a spring between two far apart dofs, as a new
  // contact or a crack makes one): the same solver splits and factorizes
  // it anew.
  {
    DynamicSparsityPattern dsp(n, n);
    for (unsigned int row = 0; row < n; ++row)
      for (auto entry = system.pattern.begin(row);
           entry != system.pattern.end(row);
           ++entry)
        dsp.add(row, entry->column());
    unsigned int a = 0, b = n - 1;
    while (system.constraints.is_constrained(a))
      ++a;
    while (system.constraints.is_constrained(b))
      --b;
    dsp.add(a, b);
    dsp.add(b, a);
    SparsityPattern pattern;
    pattern.copy_from(dsp);
    SparseMatrix<double> sprung(pattern);
    for (unsigned int row = 0; row < n; ++row)
      for (auto entry = system.matrix.begin(row);
           entry != system.matrix.end(row);
           ++entry)
        sprung.set(row, entry->column(), entry->value());
    const double k = system.matrix.diag_element(a);
    sprung.add(a, a, k);
    sprung.add(b, b, k);
    sprung.add(a, b, -k);
    sprung.add(b, a, -k);
    mumps.factorize(sprung, true);
    const Vector<double> reference =
      serial_solution(parameters::LinearSolverType::direct,
                      sprung,
                      system.gravity);
    Vector<double> x(n);
    mumps.solve(x, system.gravity);
    check(relative_difference(x, reference) <= 1e-12,
          "MUMPS agrees with CHOLMOD on a new pattern");
    check(
      relative_difference(x,
                          serial_solution(parameters::LinearSolverType::direct,
                                          system.matrix,
                                          system.gravity)) > 1e-9,
      "the spring changes the solution");
  }
  out << "a new pattern: split and factorized anew, solved to 1e-12"
      << std::endl;

  // 3c. Rows owned as the caller says (set_row_owners(), as a scene's
  // dofs are owned in its shared triangulation): the last process owns
  // the first rows, so that the split cannot be METIS's by chance; an
  // empty list gives the split back to METIS.
  {
    std::vector<unsigned int> owners(n);
    for (unsigned int i = 0; i < n; ++i)
      owners[i] = n_processes - 1 - std::size_t(i) * n_processes / n;
    mumps.set_row_owners(owners);
    mumps.factorize(system.matrix, true);
    const unsigned int this_process = Utilities::MPI::this_mpi_process(comm);
    IndexSet           given(n);
    for (unsigned int i = 0; i < n; ++i)
      if (owners[i] == this_process)
        given.add_index(i);
    check(mumps.locally_owned_rows() == given, "the rows owned as given");
    Vector<double> x(n);
    mumps.solve(x, system.gravity);
    check(
      relative_difference(x,
                          serial_solution(parameters::LinearSolverType::direct,
                                          system.matrix,
                                          system.gravity)) <= 1e-12,
      "MUMPS agrees with CHOLMOD on the rows owned as given");
    check(ndda_tests::same_on_every_process(x, comm),
          "every process has the same solution (rows owned as given)");
    mumps.set_row_owners({});
    mumps.factorize(system.matrix, true);
    check(mumps.locally_owned_rows() == owned, "METIS's split again");
  }
  out << "rows owned as the caller says: solved to 1e-12; without owners, "
         "METIS's split"
      << std::endl;

  // 4. A non-symmetric matrix: MUMPS's LU against UMFPACK.
  {
    SparseMatrix<double> skew(system.pattern);
    skew.copy_from(system.matrix);
    const double scale = system.matrix.diag_element(n / 2);
    for (unsigned int row = 0; row < n; ++row)
      for (auto entry = skew.begin(row); entry != skew.end(row); ++entry)
        if (entry->column() != row && !system.constraints.is_constrained(row))
          entry->value() +=
            (entry->column() > row ? 0.05 : -0.05) * scale * 1e-2;
    DistributedSolver lu(comm, DistributedSolver::Method::mumps);
    lu.factorize(skew, false);
    const Vector<double> reference =
      serial_solution(parameters::LinearSolverType::umfpack, skew, system.pull);
    Vector<double> x(n);
    lu.solve(x, system.pull);
    const double difference = relative_difference(x, reference);
    diagnostics << "MUMPS LU against UMFPACK: " << difference << std::endl;
    check(difference <= 1e-12, "MUMPS (LU) agrees with UMFPACK to 1e-12");
    check(
      relative_difference(x,
                          serial_solution(parameters::LinearSolverType::direct,
                                          system.matrix,
                                          system.pull)) > 1e-6,
      "the skew part changes the solution");
  }
  out << "MUMPS (LU), non-symmetric: UMFPACK's solution to 1e-12" << std::endl;

  // 5. CG-AMG with the rigid-body modes.
  {
    DistributedSolver cg(comm, DistributedSolver::Method::cg_amg, 1e-12);
    system.rigid_body_modes(cg);
    cg.factorize(system.matrix, true);
    Vector<double>     x(n);
    const unsigned int iterations = cg.solve(x, system.pull);
    Vector<double>     residual(n);
    system.matrix.residual(residual, x, system.pull);
    const Vector<double> reference =
      serial_solution(parameters::LinearSolverType::direct,
                      system.matrix,
                      system.pull);
    diagnostics << "CG-AMG: " << iterations << " iterations, residual "
                << residual.l2_norm() / system.pull.l2_norm()
                << ", against CHOLMOD " << relative_difference(x, reference)
                << std::endl;
    check(residual.l2_norm() <= 1.01e-12 * system.pull.l2_norm(),
          "CG-AMG reaches its tolerance");
    check(iterations < 60, "CG-AMG converges in fewer than 60 iterations");
    check(relative_difference(x, reference) <= 1e-9,
          "CG-AMG agrees with CHOLMOD to 1e-9");
    check(ndda_tests::same_on_every_process(x, comm),
          "every process has the same CG solution");
  }
  out << "CG-AMG: relative residual 1e-12 in fewer than 60 iterations, "
      << "CHOLMOD's solution to 1e-9" << std::endl;

  // 6. The cells split among the processes for the per-cell work
  // (OwnedCells): contiguous ranges without gap or overlap, and each
  // process's values of its cells given to all.
  {
    OwnedCells owned;
    owned.set_communicator(comm);
    const unsigned int n_cells = 1001;
    owned.reinit(n_cells);
    check(owned.n_cells() == n_cells, "OwnedCells splits every cell");
    check(owned.is_split() == (n_processes > 1),
          "the cells are split on more than one process");
    const unsigned int n_owned = owned.end() - owned.begin();
    check(Utilities::MPI::sum(n_owned, comm) == n_cells &&
            Utilities::MPI::min(n_owned, comm) + 1 >=
              Utilities::MPI::max(n_owned, comm),
          "the ranges hold every cell once, as equal as they can be");
    // The next process's range starts where this one's ends.
    const auto ends         = Utilities::MPI::all_gather(comm, owned.end());
    const auto this_process = Utilities::MPI::this_mpi_process(comm);
    check(owned.begin() == (this_process == 0 ? 0 : ends[this_process - 1]),
          "the ranges are contiguous");

    // A value that tells the cell and the entry.
    const auto value = [](const unsigned int c, const unsigned int i) {
      return Tensor<1, 2>({c + 0.25 * i, -1. * c});
    };
    const Tensor<1, 2>        unset({-7., -7.});
    std::vector<Tensor<1, 2>> values(n_cells * 3, unset);
    for (unsigned int c = owned.begin(); c < owned.end(); ++c)
      for (unsigned int i = 0; i < 3; ++i)
        values[c * 3 + i] = value(c, i);
    owned.share(values, 3);
    bool all = true;
    for (unsigned int c = 0; c < n_cells; ++c)
      for (unsigned int i = 0; i < 3; ++i)
        all = all && values[c * 3 + i] == value(c, i);
    check(all, "share(): every process has every cell's values");

    // Every third cell only: the others keep what they had.
    std::vector<unsigned int> some;
    for (unsigned int c = 1; c < n_cells; c += 3)
      some.push_back(c);
    std::vector<double> scalars(n_cells, -1.);
    for (const unsigned int c : some)
      if (c >= owned.begin() && c < owned.end())
        scalars[c] = c;
    owned.share(scalars, 1, some);
    all = true;
    for (unsigned int c = 0; c < n_cells; ++c)
      all = all && scalars[c] == (c % 3 == 1 ? double(c) : -1.);
    check(all, "share() of some cells: those cells' values, no other");
  }
  out << "cells split among the processes without gap or overlap, their "
      << "values shared" << std::endl;

  // 7. Work of the first process alone (SerialWork): on the threads and
  // the cores of every process of its machine (all of them here), back to
  // its own after; its error thrown on every process.
  {
    const SerialWork   serial(comm);
    const unsigned int own_threads = MultithreadInfo::n_threads();
    const bool         first = Utilities::MPI::this_mpi_process(comm) == 0;
    // The cores of this process, and of all (every process is on this
    // machine).
    cpu_set_t own, all, in_work, after;
    CPU_ZERO(&own);
    CPU_ZERO(&all);
    CPU_ZERO(&in_work);
    CPU_ZERO(&after);
    sched_getaffinity(0, sizeof(own), &own);
    std::vector<cpu_set_t> cores(n_processes);
    MPI_Allgather(&own,
                  sizeof(cpu_set_t),
                  MPI_BYTE,
                  cores.data(),
                  sizeof(cpu_set_t),
                  MPI_BYTE,
                  comm);
    for (const auto &c : cores)
      CPU_OR(&all, &all, &c);
    unsigned int threads_in_work = 0;
    int          arena_threads   = 0;
    unsigned int calls           = 0;
    serial.run([&]() {
      ++calls;
      threads_in_work = MultithreadInfo::n_threads();
      arena_threads   = tbb::this_task_arena::max_concurrency();
      sched_getaffinity(0, sizeof(in_work), &in_work);
    });
    sched_getaffinity(0, sizeof(after), &after);
    check(calls == (first ? 1u : 0u), "the work runs on the first process");
    // No more threads than the cores of all processes.
    const unsigned int processes =
      std::max(1u, std::min(n_processes, CPU_COUNT(&all) / own_threads));
    check(!first || serial.processes_on_first_machine() == processes,
          "the processes on the first machine, as many as their cores allow");
    const unsigned int expected =
      std::getenv("DEAL_II_NUM_THREADS") != nullptr ?
        threads_in_work : // the environment caps it
        own_threads * processes;
    check(!first || threads_in_work == expected,
          "the first process works on the threads of every process");
    check(!first || arena_threads == static_cast<int>(own_threads * processes),
          "in an arena of as many threads");
    check(!first || processes == 1 || CPU_EQUAL(&in_work, &all),
          "on the cores of every process");
    check(CPU_EQUAL(&after, &own), "and goes back to its own cores");
    check(MultithreadInfo::n_threads() == own_threads,
          "and goes back to its own number of threads");
    std::string message;
    try
      {
        serial.run(
          []() { AssertThrow(false, ExcMessage("no factorization here")); });
      }
    catch (const ExceptionBase &exc)
      {
        std::ostringstream text;
        exc.print_info(text);
        message = text.str();
      }
    check(message.find("no factorization here") != std::string::npos,
          "the first process's error is thrown on every process");
  }
  out << "work of the first process alone: on every process's threads, "
      << "its error thrown on all" << std::endl;
  return 0;
}
