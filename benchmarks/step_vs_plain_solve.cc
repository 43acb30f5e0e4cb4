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
 *   solver settings and ndda's own overhead can be told apart. The
 *   "matched re-solve", against which the steady step is judged (issue
 *   19: at most 1.5 times), is the mean of
 *   plain_system::n_matched_resolves back-substitutions after the first
 *   solve, as the steady step is the mean of several steps;
 * - ndda's own linear solve inside its steady steps (its timer's
 *   "linear solve" less "factorize": here one back-substitution of the
 *   same matrix a step), and the steady step over it ("per-step/own
 *   solve"): what ndda's own work adds to the solve under the cache state
 *   of a real step.
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
 * The scene and the plain solve are in plain_system.h; the same solve
 * on several MPI processes is benchmarks/distributed_solve.cc.
 *
 * Usage: step_vs_plain_solve [target n_dofs ...] [--repeat N]
 *        [--solver UMFPACK|direct]
 *        (default: 1e4 1e5, ndda's default solver)
 */

#include <deal.II/base/mpi.h>
#include <deal.II/base/multithread_info.h>
#include <deal.II/base/table_handler.h>

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <map>
#include <numeric>
#include <string>
#include <vector>

#include "plain_system.h"

using namespace dealii;
using namespace plain_system;

namespace
{
  /** The steady steps timed after the first: NDDA_STEADY_STEPS, or 10. */
  unsigned int
  n_steady_steps()
  {
    const char *text = std::getenv("NDDA_STEADY_STEPS");
    return text != nullptr && std::atoi(text) > 0 ? std::atoi(text) : 10;
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
          // ndda's own linear solves in the steady steps (timer sections
          // "linear solve" less "factorize"), per step.
          double ndda_step_solve = 0;
          auto   matched_type    = ndda::parameters::LinearSolverType::umfpack;
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
            first_step               = seconds_since(start);
            ndda_first               = simulator.get_displacement();
            const auto &timer        = simulator.get_timer();
            const auto  solve_so_far = [&timer]() {
              return timer.section_time("linear solve") -
                     timer.section_time("factorize");
            };
            const double solve_before = solve_so_far();
            for (unsigned int s = 0; s < n_steady_steps(); ++s)
              {
                start = Clock::now();
                simulator.do_time_step();
                steady.push_back(seconds_since(start));
              }
            ndda_step_solve =
              (solve_so_far() - solve_before) / n_steady_steps();
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
                    << " s, factorizations " << n_factorizations
                    << ", linear solve in a steady step " << ndda_step_solve
                    << " s" << std::endl;

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
                    << plain.matched_solve_time << " s, re-solve (mean of "
                    << n_matched_resolves << ") " << plain.matched_resolve_time
                    << " s (min " << plain.matched_resolve_min << ", max "
                    << plain.matched_resolve_max << " s)"
                    << ", difference to SparseDirectUMFPACK "
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
            ratios[key + "step_own_solve"].push_back(mean_step /
                                                     ndda_step_solve);
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
          timing.add_value("per-step/own solve", mean_step / ndda_step_solve);
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
          detail.add_value("ndda solve per steady step (s)", ndda_step_solve);
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
          detail.add_value("matched re-solve min (s)",
                           plain.matched_resolve_min);
          detail.add_value("matched re-solve max (s)",
                           plain.matched_resolve_max);
        }

      for (const auto &column : {"ndda first step (s)",
                                 "ndda per step (s)",
                                 "plain solve total (s)"})
        timing.set_precision(column, 4);
      for (const auto &column : {"first/plain",
                                 "per-step/plain",
                                 "per-step/plain re-solve",
                                 "first/matched",
                                 "per-step/matched re-solve",
                                 "per-step/own solve"})
        timing.set_precision(column, 3);
      timing.set_precision("peak RSS (MB)", 1);
      timing.set_precision("bytes/DoF", 0);
      timing.set_scientific("rel. l2 diff", true);
      timing.set_precision("rel. l2 diff", 2);
      for (const auto &column : {"ndda setup (s)",
                                 "ndda steady min (s)",
                                 "ndda steady max (s)",
                                 "ndda solve per steady step (s)",
                                 "plain setup (s)",
                                 "plain assembly (s)",
                                 "plain factorize (s)",
                                 "plain solve (s)",
                                 "plain re-solve (s)",
                                 "matched factorize (s)",
                                 "matched solve (s)",
                                 "matched re-solve (s)",
                                 "matched re-solve min (s)",
                                 "matched re-solve max (s)"})
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
          // Issue 19: a steady step <= 1.5 x a matched back-substitution,
          // the plain program's or ndda's own within its steps.
          for (const std::string yardstick : {"step_matched", "step_own_solve"})
            if (key.size() > yardstick.size() &&
                key.substr(key.size() - yardstick.size()) == yardstick)
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
