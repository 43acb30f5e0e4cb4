// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_benchmarks_plain_system_h
#define ndda_benchmarks_plain_system_h

/**
 * @file
 * The scene of step_vs_plain_solve (one P1 block, 4 m x 1 m, Newmark,
 * gravity, pressure on the top edge, left edge fixed; see that file's
 * comment), and the plain deal.II solve of its first step on a copy of
 * ndda's triangulation, shared by step_vs_plain_solve and
 * distributed_solve. Each benchmark is one translation unit that includes
 * it once.
 */

#include <deal.II/base/mpi.h>
#include <deal.II/base/multithread_info.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/table_handler.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_fe.h>

#include <deal.II/grid/tria.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <ndda/parameters/parameters.h>
#include <ndda/physics/linear_solver.h>
#include <ndda/simulator.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <malloc.h>
#include <map>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

namespace plain_system
{
  using namespace dealii;

  // The scene; the plain solve uses the same numbers.
  const double length = 4., height = 1.;
  const double density = 2500., youngs_modulus = 10e9, poissons_ratio = 0.25;
  const double thickness = 1.;
  const double gravity   = -9.81; // m/s^2, y direction
  const double pressure  = 1e5;   // Pa on the top edge
  const double time_step = 1e-4;  // s

  using Clock = std::chrono::steady_clock;

  inline double
  seconds_since(const Clock::time_point start)
  {
    return std::chrono::duration<double>(Clock::now() - start).count();
  }


  /** A field of /proc/self/status in bytes (VmHWM, VmRSS), or -1. */
  inline double
  status_bytes(const std::string &field)
  {
    std::ifstream status("/proc/self/status");
    std::string   line;
    while (std::getline(status, line))
      if (line.rfind(field + ":", 0) == 0)
        return std::stod(line.substr(field.size() + 1)) * 1024.;
    return -1.;
  }


  /**
   * Return freed memory to the system and reset VmHWM to the current
   * resident size (Linux: write 5 to clear_refs).
   */
  inline void
  reset_peak_rss()
  {
    malloc_trim(0);
    std::ofstream clear_refs("/proc/self/clear_refs");
    if (clear_refs)
      clear_refs << "5" << std::flush;
  }


  inline std::string
  scene_text(const unsigned int target_n_cells, const std::string &solver)
  {
    std::ostringstream s;
    s << std::setprecision(17);
    s << "set Scene name = step_vs_plain_solve\n"
      << "subsection Control\n"
      << "  set Analysis type = dynamic\n"
      << "  set Time integrator = Newmark\n"
      << "  set Time step = " << time_step << "\n"
      << "  set End time = 1\n"
      << "  set Element degree = 1\n"
      << (solver.empty() ? "" : "  set Linear solver = " + solver + "\n")
      << "end\n"
      << "subsection Materials\n"
      << "  set Names = rock\n"
      << "  set Plane condition = plane stress\n"
      << "  set Thickness = " << thickness << "\n"
      << "  subsection rock\n"
      << "    set Density = " << density << "\n"
      << "    set Young's modulus = " << youngs_modulus << "\n"
      << "    set Poisson's ratio = " << poissons_ratio << "\n"
      << "  end\n"
      << "end\n"
      << "subsection Geometry\n"
      << "  set Blocks = block\n"
      << "  subsection block\n"
      << "    set Outer boundary = 0, 0; " << length << ", 0; " << length
      << ", " << height << "; 0, " << height << "\n"
      << "    set Material = rock\n"
      << "    set Target number of elements = " << target_n_cells << "\n"
      << "  end\n"
      << "end\n"
      << "subsection Loads\n"
      << "  set Gravity = 0; " << gravity << "\n"
      << "  set Line loads = top\n"
      << "  subsection top\n"
      << "    set Segment = 0, " << height << ", " << length << ", " << height
      << "\n"
      << "    set Type = pressure\n"
      << "    set Value = " << pressure << "\n"
      << "  end\n"
      << "end\n"
      << "subsection Boundary conditions\n"
      << "  set Names = left\n"
      << "  subsection left\n"
      << "    set Type = fixed\n"
      << "    set Segments = 0, 0, 0, " << height << "\n"
      << "  end\n"
      << "end\n"
      << "subsection Output\n"
      << "  set Write vtu = false\n"
      << "end\n";
    return s.str();
  }


  struct PlainResult
  {
    double         setup_time     = 0;
    double         assembly_time  = 0;
    double         factorize_time = 0;
    double         solve_time     = 0;
    double         resolve_time   = 0;
    double         peak_rss       = 0;
    Vector<double> solution;
    /// ndda's LinearSolver with ndda's settings: factorization (including
    /// the copy to the solver's arrays), the first solve, the mean, the
    /// fastest and the slowest of n_matched_resolves more solves, and the
    /// relative l2 difference of its solution to SparseDirectUMFPACK's.
    double matched_factorize_time = 0;
    double matched_solve_time     = 0;
    double matched_resolve_time   = 0;
    double matched_resolve_min    = 0;
    double matched_resolve_max    = 0;
    double matched_difference     = 0;
  };

  /**
   * The re-solves that the matched back-substitution is the mean of. One
   * back-substitution spreads by about 50 % from run to run on the
   * reference machine (doc/performance.md, "Vertices in the order of the
   * cells"), as ndda's steps do; ndda's side is the mean of its steady
   * steps, so this side is a mean too. The re-solves follow each other,
   * so that a small system's factors stay in the caches, as they do
   * within ndda's steps (at 1e4 DoFs ndda's own solve in a step takes
   * what a re-solve from the caches does, a third of one from memory).
   */
  constexpr unsigned int n_matched_resolves = 10;

  /**
   * Factorize and solve @p matrix x = @p rhs with ndda's own LinearSolver
   * of @p type, the one of the ndda run (UMFPACK: symmetric strategy, no
   * iterative refinement; direct: CHOLMOD's Cholesky where the matrix is
   * symmetric positive definite, as here), so that the "matched" columns
   * use exactly ndda's solver settings.
   */
  inline void
  matched_solve(const ndda::parameters::LinearSolverType type,
                const SparseMatrix<double>              &matrix,
                const Vector<double>                    &rhs,
                const AffineConstraints<double>         &constraints,
                PlainResult                             &result)
  {
    auto               start = Clock::now();
    ndda::LinearSolver solver(type, 0.);
    solver.factorize(matrix);
    result.matched_factorize_time = seconds_since(start);

    Vector<double> x(matrix.m());
    start = Clock::now();
    solver.solve(x, rhs);
    constraints.distribute(x);
    result.matched_solve_time = seconds_since(start);
    std::vector<double> resolves;
    for (unsigned int r = 0; r < n_matched_resolves; ++r)
      {
        start = Clock::now();
        solver.solve(x, rhs);
        constraints.distribute(x);
        resolves.push_back(seconds_since(start));
      }
    result.matched_resolve_time =
      std::accumulate(resolves.begin(), resolves.end(), 0.) / resolves.size();
    result.matched_resolve_min =
      *std::min_element(resolves.begin(), resolves.end());
    result.matched_resolve_max =
      *std::max_element(resolves.begin(), resolves.end());
    x -= result.solution;
    result.matched_difference = x.l2_norm() / result.solution.l2_norm();
  }


  /**
   * What a program may do with the plain system once it is solved: the
   * DoFHandler, mapping, matrix, right-hand side, constraints and solution.
   */
  using AfterPlainSolve = std::function<void(const DoFHandler<2> &,
                                             const Mapping<2> &,
                                             const SparseMatrix<double> &,
                                             const Vector<double> &,
                                             const AffineConstraints<double> &,
                                             const Vector<double> &)>;


  /**
   * The plain deal.II solve of the first Newmark step: step-8 with the
   * effective matrix K + 4/dt^2 M and the right-hand side 2 f (see the file
   * comment).
   */
  inline PlainResult
  plain_solve(const Triangulation<2>                  &triangulation,
              const ndda::parameters::LinearSolverType matched_type,
              const AfterPlainSolve                   &after = {})
  {
    PlainResult result;
    auto        start = Clock::now();

    const FESystem<2>      fe(FE_SimplexP<2>(1), 2);
    const MappingFE<2>     mapping(FE_SimplexP<2>(1));
    const QGaussSimplex<2> quadrature(2);
    const QGaussSimplex<1> face_quadrature(2);
    DoFHandler<2>          dof_handler(triangulation);
    dof_handler.distribute_dofs(fe);

    // Fixed left edge, and which faces carry the pressure.
    const double                         tolerance = 1e-8 * length;
    AffineConstraints<double>            constraints;
    std::vector<types::global_dof_index> face_dofs(fe.n_dofs_per_face());
    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->at_boundary(f) &&
            std::abs(cell->face(f)->vertex(0)[0]) < tolerance &&
            std::abs(cell->face(f)->vertex(1)[0]) < tolerance)
          {
            cell->face(f)->get_dof_indices(face_dofs);
            for (const auto dof : face_dofs)
              if (!constraints.is_constrained(dof))
                constraints.add_line(dof);
          }
    constraints.close();

    DynamicSparsityPattern dsp(dof_handler.n_dofs());
    DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
    SparsityPattern sparsity_pattern;
    sparsity_pattern.copy_from(dsp);
    SparseMatrix<double> system_matrix(sparsity_pattern);
    Vector<double>       system_rhs(dof_handler.n_dofs());
    result.solution.reinit(dof_handler.n_dofs());
    result.setup_time = seconds_since(start);

    // Assembly, step-8 style.
    start           = Clock::now();
    const double mu = youngs_modulus / (2. * (1. + poissons_ratio));
    const double lambda =
      youngs_modulus * poissons_ratio /
      (1. - poissons_ratio * poissons_ratio); // plane stress
    const double       c_mass = 4. / (time_step * time_step);
    const double       factor = 2.; // f(0) + f(dt), constant loads
    const Tensor<1, 2> body_force({0., density * gravity});
    const Tensor<1, 2> traction({0., -pressure}); // -p n on the top edge

    FEValues<2>        fe_values(mapping,
                          fe,
                          quadrature,
                          update_values | update_gradients | update_JxW_values);
    FEFaceValues<2>    fe_face_values(mapping,
                                   fe,
                                   face_quadrature,
                                   update_values | update_JxW_values);
    const unsigned int dofs_per_cell = fe.n_dofs_per_cell();
    FullMatrix<double> cell_matrix(dofs_per_cell, dofs_per_cell);
    Vector<double>     cell_rhs(dofs_per_cell);
    std::vector<types::global_dof_index> local_dof_indices(dofs_per_cell);

    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell_matrix = 0;
        cell_rhs    = 0;
        fe_values.reinit(cell);
        for (const unsigned int q : fe_values.quadrature_point_indices())
          {
            const double JxW = fe_values.JxW(q) * thickness;
            for (const unsigned int i : fe_values.dof_indices())
              {
                const unsigned int component_i =
                  fe.system_to_component_index(i).first;
                const Tensor<1, 2> grad_i = fe_values.shape_grad(i, q);
                const double       phi_i  = fe_values.shape_value(i, q);
                for (const unsigned int j : fe_values.dof_indices())
                  {
                    const unsigned int component_j =
                      fe.system_to_component_index(j).first;
                    const Tensor<1, 2> grad_j = fe_values.shape_grad(j, q);
                    cell_matrix(i, j) +=
                      (grad_i[component_i] * grad_j[component_j] * lambda +
                       grad_i[component_j] * grad_j[component_i] * mu +
                       (component_i == component_j ?
                          grad_i * grad_j * mu + c_mass * density * phi_i *
                                                   fe_values.shape_value(j, q) :
                          0.)) *
                      JxW;
                  }
                cell_rhs(i) += factor * phi_i * body_force[component_i] * JxW;
              }
          }
        for (const unsigned int f : cell->face_indices())
          if (cell->at_boundary(f) &&
              std::abs(cell->face(f)->vertex(0)[1] - height) < tolerance &&
              std::abs(cell->face(f)->vertex(1)[1] - height) < tolerance)
            {
              fe_face_values.reinit(cell, f);
              for (const unsigned int q :
                   fe_face_values.quadrature_point_indices())
                for (const unsigned int i : fe_face_values.dof_indices())
                  {
                    const unsigned int component_i =
                      fe.system_to_component_index(i).first;
                    cell_rhs(i) += factor * fe_face_values.shape_value(i, q) *
                                   traction[component_i] *
                                   fe_face_values.JxW(q) * thickness;
                  }
            }
        cell->get_dof_indices(local_dof_indices);
        constraints.distribute_local_to_global(
          cell_matrix, cell_rhs, local_dof_indices, system_matrix, system_rhs);
      }
    result.assembly_time = seconds_since(start);

    {
      start = Clock::now();
      SparseDirectUMFPACK solver;
      solver.initialize(system_matrix);
      result.factorize_time = seconds_since(start);

      start = Clock::now();
      solver.vmult(result.solution, system_rhs);
      constraints.distribute(result.solution);
      result.solve_time = seconds_since(start);

      // What a plain time stepper pays at least per later step: one more
      // back-substitution with the same factorization.
      Vector<double> second(dof_handler.n_dofs());
      start = Clock::now();
      solver.vmult(second, system_rhs);
      constraints.distribute(second);
      result.resolve_time = seconds_since(start);
    }
    result.peak_rss = status_bytes("VmHWM");

    matched_solve(matched_type, system_matrix, system_rhs, constraints, result);
    if (after)
      after(dof_handler,
            mapping,
            system_matrix,
            system_rhs,
            constraints,
            result.solution);
    return result;
  }
} // namespace plain_system

#endif
