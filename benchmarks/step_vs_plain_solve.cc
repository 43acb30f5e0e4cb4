// SPDX-License-Identifier: GPL-3.0-or-later

/**
 * @file
 * What one ndda time step costs compared with a plain deal.II solve of the
 * same linear system.
 *
 * For each target size (about 1e4, 1e5, 1e6 degrees of freedom) one
 * rectangular block, 4 m x 1 m, P1, plane stress, dynamic analysis with
 * Newmark, gravity and a constant pressure on the top edge, left edge
 * fixed, is built through ndda's Parameters and Simulator. Measured:
 *
 * - ndda, first step: one call of Simulator::do_time_step() after setup()
 *   (element matrices, global assembly, the initial acceleration solve
 *   M a0 = f(0) that Newmark needs, factorization of the effective matrix
 *   and the solve);
 * - ndda, steady step: the mean of the next steps, where ndda reuses its
 *   element matrices and its factorization;
 * - a plain deal.II program, step-8 style, on a copy of ndda's
 *   triangulation (taken before the first step moves the mesh) with the
 *   same element, mapping, quadrature and direct solver: assembly of the
 *   effective Newmark matrix K + 4/dt^2 M and the load vector with
 *   FEValues, the fixed left edge through AffineConstraints and
 *   distribute_local_to_global(), SparseDirectUMFPACK factorization and
 *   solve. DoF distribution and the sparsity pattern are timed apart and
 *   are not in the plain total, as ndda's setup() is not in its first
 *   step. A second back-substitution with the same factorization ("plain
 *   re-solve") is the least a plain time-stepping code pays per step.
 * - the same plain system once more, factorized and solved by ndda's own
 *   LinearSolver of the ndda run's solver type, with its settings
 *   (`direct`, the default: CHOLMOD's Cholesky factorization, since the
 *   system is symmetric positive definite; UMFPACK: symmetric strategy, no
 *   iterative refinement, where SparseDirectUMFPACK uses UMFPACK's
 *   defaults, whose iterative refinement costs at least one extra residual
 *   per solve). The "matched" columns compare ndda with this, so that
 *   solver settings and ndda's own overhead can be told apart.
 *
 * The comparison is only fair if both solve the same system. With zero
 * initial velocity, no initial stress and constant loads f, ndda's first
 * Newmark step solves (K + 4/dt^2 M) d = f(dt) + M a0 with M a0 = f(0) on
 * the free DoFs, that is (K + 4/dt^2 M) d = 2 f. The plain program assembles
 * exactly that right-hand side, and both number the DoFs the same way (same
 * triangulation, same element, no renumbering), so the relative l2
 * difference of the two solution vectors must be at round-off level; it is
 * printed.
 *
 * Memory: the peak resident set size (VmHWM of /proc/self/status) is reset
 * (/proc/self/clear_refs) before each ndda run and read after its last
 * step; "bytes per DoF" is that peak less the resident size at the start of
 * the case and less the triangulation copy kept for the plain solve,
 * divided by the number of DoFs.
 *
 * With NDDA_STEADY_STEPS=N, N steady steps are timed (default 10; more
 * for a profile of the steady step), and with NDDA_TIMER_TABLE=1 ndda's
 * timer table of each case goes to stderr.
 *
 * Usage: step_vs_plain_solve [target n_dofs ...] [--repeat N]
 *        [--solver UMFPACK|direct]   (default: 1e4 1e5, ndda's default solver)
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
#include <iomanip>
#include <iostream>
#include <malloc.h>
#include <map>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

using namespace dealii;

namespace
{
  // The scene; the plain solve uses the same numbers.
  const double length = 4., height = 1.;
  const double density = 2500., youngs_modulus = 10e9, poissons_ratio = 0.25;
  const double thickness = 1.;
  const double gravity   = -9.81; // m/s^2, y direction
  const double pressure  = 1e5;   // Pa on the top edge
  const double time_step = 1e-4;  // s
  /** The steady steps timed after the first: NDDA_STEADY_STEPS, or 10. */
  unsigned int
  n_steady_steps()
  {
    const char *text = std::getenv("NDDA_STEADY_STEPS");
    return text != nullptr && std::atoi(text) > 0 ? std::atoi(text) : 10;
  }

  using Clock = std::chrono::steady_clock;

  double
  seconds_since(const Clock::time_point start)
  {
    return std::chrono::duration<double>(Clock::now() - start).count();
  }


  /** A field of /proc/self/status in bytes (VmHWM, VmRSS), or -1. */
  double
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
  void
  reset_peak_rss()
  {
    malloc_trim(0);
    std::ofstream clear_refs("/proc/self/clear_refs");
    if (clear_refs)
      clear_refs << "5" << std::flush;
  }


  std::string
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
    /// the copy to the solver's arrays), solve, one more solve, and the
    /// relative l2 difference of its solution to SparseDirectUMFPACK's.
    double matched_factorize_time = 0;
    double matched_solve_time     = 0;
    double matched_resolve_time   = 0;
    double matched_difference     = 0;
  };


  /**
   * Factorize and solve @p matrix x = @p rhs with ndda's own LinearSolver
   * of @p type, the one of the ndda run (UMFPACK: symmetric strategy, no
   * iterative refinement; direct: CHOLMOD's Cholesky where the matrix is
   * symmetric positive definite, as here), so that the "matched" columns
   * use exactly ndda's solver settings.
   */
  void
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
    for (double *time :
         {&result.matched_solve_time, &result.matched_resolve_time})
      {
        start = Clock::now();
        solver.solve(x, rhs);
        constraints.distribute(x);
        *time = seconds_since(start);
      }
    x -= result.solution;
    result.matched_difference = x.l2_norm() / result.solution.l2_norm();
  }


  /**
   * The plain deal.II solve of the first Newmark step: step-8 with the
   * effective matrix K + 4/dt^2 M and the right-hand side 2 f (see the file
   * comment).
   */
  PlainResult
  plain_solve(const Triangulation<2>                  &triangulation,
              const ndda::parameters::LinearSolverType matched_type)
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
    return result;
  }
} // namespace



int
main(int argc, char **argv)
{
  try
    {
      // deal.II's threads: as many as cores, or DEAL_II_NUM_THREADS.
      Utilities::MPI::MPI_InitFinalize mpi(argc,
                                           argv,
                                           numbers::invalid_unsigned_int);
      std::cout << "threads: " << MultithreadInfo::n_threads() << std::endl;

      // Arguments: target DoF counts (default 1e4 and 1e5),
      // '--repeat N' to measure each N times: the figures for
      // doc/validation.md are then the medians (single runs vary by about
      // +-25 % on the reference machine, see doc/performance.md), and
      // '--solver NAME' for ndda's Control/Linear solver (default: ndda's
      // default), which the matched solve then uses too.
      std::vector<double> sizes;
      unsigned int        repeats = 1;
      std::string         solver;
      for (int a = 1; a < argc; ++a)
        if (std::string(argv[a]) == "--repeat" && a + 1 < argc)
          repeats = std::stoi(argv[++a]);
        else if (std::string(argv[a]) == "--solver" && a + 1 < argc)
          solver = argv[++a];
        else
          sizes.push_back(std::stod(argv[a]));
      if (sizes.empty())
        sizes = {1e4, 1e5};
      std::vector<double> targets;
      for (const double size : sizes)
        for (unsigned int r = 0; r < std::max(repeats, 1u); ++r)
          targets.push_back(size);
      std::map<std::string, std::vector<double>> ratios; // for the page

      TableHandler timing, detail;
      for (const double target : targets)
        {
          std::cout << "target " << target << " DoFs" << std::endl;
          reset_peak_rss();
          const double baseline_rss = status_bytes("VmRSS");

          // ndda: setup, first step, steady steps.
          Triangulation<2>    triangulation;
          Vector<double>      ndda_first;
          double              setup_time = 0, first_step = 0;
          std::vector<double> steady;
          unsigned int        n_dofs = 0, n_cells = 0, n_factorizations = 0;
          double              ndda_peak_rss = 0;
          auto matched_type = ndda::parameters::LinearSolverType::umfpack;
          {
            ParameterHandler             prm;
            ndda::parameters::Parameters parameters;
            parameters.read(scene_text(static_cast<unsigned int>(target),
                                       solver),
                            "step_vs_plain_solve.prm",
                            prm);
            matched_type = parameters.control.linear_solver;
            ndda::Simulator<2> simulator(parameters);
            auto               start = Clock::now();
            simulator.setup();
            setup_time = seconds_since(start);
            n_dofs     = simulator.get_dof_handler().n_dofs();
            n_cells = simulator.get_mesh().get_triangulation().n_active_cells();
            // Copy before the first step moves the vertices.
            triangulation.copy_triangulation(
              simulator.get_mesh().get_triangulation());
            std::cout << "  " << n_cells << " cells, " << n_dofs
                      << " DoFs, setup " << setup_time << " s" << std::endl;

            start = Clock::now();
            simulator.do_time_step();
            first_step = seconds_since(start);
            ndda_first = simulator.get_displacement();
            for (unsigned int s = 0; s < n_steady_steps(); ++s)
              {
                start = Clock::now();
                simulator.do_time_step();
                steady.push_back(seconds_since(start));
              }
            n_factorizations = simulator.n_factorizations();
            ndda_peak_rss    = status_bytes("VmHWM");
            if (std::getenv("NDDA_TIMER_TABLE") != nullptr)
              simulator.get_timer().print_summary(std::cerr);
          }
          const double mean_step =
            std::accumulate(steady.begin(), steady.end(), 0.) / steady.size();
          const double bytes_per_dof = (ndda_peak_rss - baseline_rss -
                                        triangulation.memory_consumption()) /
                                       n_dofs;
          std::cout << "  ndda first step " << first_step
                    << " s, steady steps min/mean/max "
                    << *std::min_element(steady.begin(), steady.end()) << " / "
                    << mean_step << " / "
                    << *std::max_element(steady.begin(), steady.end())
                    << " s, factorizations " << n_factorizations << std::endl;

          // The plain solve on the same mesh.
          reset_peak_rss();
          const PlainResult plain = plain_solve(triangulation, matched_type);
          const double      plain_total =
            plain.assembly_time + plain.factorize_time + plain.solve_time;
          const double matched_total = plain.assembly_time +
                                       plain.matched_factorize_time +
                                       plain.matched_solve_time;
          AssertThrow(plain.solution.size() == ndda_first.size(),
                      ExcMessage("ndda and the plain solve have different "
                                 "numbers of DoFs."));
          Vector<double> difference(ndda_first);
          difference -= plain.solution;
          const double relative_difference =
            difference.l2_norm() / plain.solution.l2_norm();
          std::cout << "  plain setup " << plain.setup_time << " s, assembly "
                    << plain.assembly_time << " s, factorize "
                    << plain.factorize_time << " s, solve " << plain.solve_time
                    << " s, re-solve " << plain.resolve_time << " s"
                    << std::endl
                    << "  plain, ndda's solver as ndda calls it: factorize "
                    << plain.matched_factorize_time << " s, solve "
                    << plain.matched_solve_time << " s, re-solve "
                    << plain.matched_resolve_time
                    << " s, difference to SparseDirectUMFPACK "
                    << plain.matched_difference << std::endl
                    << "  |d_ndda - d_plain| / |d_plain| = "
                    << relative_difference
                    << "  (|d_plain| = " << plain.solution.l2_norm() << " m)"
                    << std::endl;

          {
            const std::string key =
              "step_vs_plain_solve." +
              std::to_string(int(std::round(std::log10(target)))) + ".";
            ratios[key + "first_plain"].push_back(first_step / plain_total);
            ratios[key + "step_resolve"].push_back(mean_step /
                                                   plain.resolve_time);
            ratios[key + "first_matched"].push_back(first_step / matched_total);
            ratios[key + "step_matched"].push_back(mean_step /
                                                   plain.matched_resolve_time);
          }
          timing.add_value("n_dofs", n_dofs);
          timing.add_value("ndda first step (s)", first_step);
          timing.add_value("ndda per step (s)", mean_step);
          timing.add_value("plain solve total (s)", plain_total);
          timing.add_value("first/plain", first_step / plain_total);
          timing.add_value("per-step/plain", mean_step / plain_total);
          timing.add_value("per-step/plain re-solve",
                           mean_step / plain.resolve_time);
          timing.add_value("first/matched", first_step / matched_total);
          timing.add_value("per-step/matched re-solve",
                           mean_step / plain.matched_resolve_time);
          timing.add_value("peak RSS (MB)", ndda_peak_rss / 1e6);
          timing.add_value("bytes/DoF", bytes_per_dof);
          timing.add_value("rel. l2 diff", relative_difference);

          detail.add_value("n_dofs", n_dofs);
          detail.add_value("cells", n_cells);
          detail.add_value("ndda setup (s)", setup_time);
          detail.add_value("ndda steady min (s)",
                           *std::min_element(steady.begin(), steady.end()));
          detail.add_value("ndda steady max (s)",
                           *std::max_element(steady.begin(), steady.end()));
          detail.add_value("ndda factorizations", n_factorizations);
          detail.add_value("plain setup (s)", plain.setup_time);
          detail.add_value("plain assembly (s)", plain.assembly_time);
          detail.add_value("plain factorize (s)", plain.factorize_time);
          detail.add_value("plain solve (s)", plain.solve_time);
          detail.add_value("plain re-solve (s)", plain.resolve_time);
          detail.add_value("plain peak RSS (MB)", plain.peak_rss / 1e6);
          detail.add_value("matched factorize (s)",
                           plain.matched_factorize_time);
          detail.add_value("matched solve (s)", plain.matched_solve_time);
          detail.add_value("matched re-solve (s)", plain.matched_resolve_time);
        }

      for (const auto &column : {"ndda first step (s)",
                                 "ndda per step (s)",
                                 "plain solve total (s)"})
        timing.set_precision(column, 4);
      for (const auto &column : {"first/plain",
                                 "per-step/plain",
                                 "per-step/plain re-solve",
                                 "first/matched",
                                 "per-step/matched re-solve"})
        timing.set_precision(column, 3);
      timing.set_precision("peak RSS (MB)", 1);
      timing.set_precision("bytes/DoF", 0);
      timing.set_scientific("rel. l2 diff", true);
      timing.set_precision("rel. l2 diff", 2);
      for (const auto &column : {"ndda setup (s)",
                                 "ndda steady min (s)",
                                 "ndda steady max (s)",
                                 "plain setup (s)",
                                 "plain assembly (s)",
                                 "plain factorize (s)",
                                 "plain solve (s)",
                                 "plain re-solve (s)",
                                 "matched factorize (s)",
                                 "matched solve (s)",
                                 "matched re-solve (s)"})
        detail.set_precision(column, 4);
      detail.set_precision("plain peak RSS (MB)", 1);
      std::cout << std::endl;
      timing.write_text(std::cout, TableHandler::org_mode_table);
      std::cout << std::endl;
      detail.write_text(std::cout, TableHandler::org_mode_table);

      // For doc/validation.md (scripts/validation_page.py): the median of
      // the repeats and their range; the goals (first step <= 1.2 x the
      // plain solve, steady step <= 1.5 x the matched re-solve) judged on
      // the median.
      std::cout << std::endl << std::setprecision(3);
      for (auto &[key, values] : ratios)
        {
          std::sort(values.begin(), values.end());
          const double median = values[values.size() / 2];
          std::cout << "@value " << key << ' ' << median << "\n@value " << key
                    << "_range " << values.front() << "-" << values.back()
                    << std::endl;
          if (key.size() > 11 && key.substr(key.size() - 11) == "first_plain")
            std::cout << "@value " << key.substr(0, key.size() - 11)
                      << "first_met " << (median <= 1.2 ? "met" : "**NOT met**")
                      << std::endl;
          // Issue 19: a steady step <= 1.5 x a matched back-substitution.
          if (key.size() > 12 && key.substr(key.size() - 12) == "step_matched")
            std::cout << "@value " << key << "_met "
                      << (median <= 1.5 ? "met" : "**NOT met**") << std::endl;
        }
      std::cout << "@value step_vs_plain_solve.repeats "
                << std::max(repeats, 1u) << std::endl;
    }
  catch (const std::exception &exc)
    {
      std::cerr << "step_vs_plain_solve: " << exc.what() << std::endl;
      return 1;
    }
  return 0;
}
