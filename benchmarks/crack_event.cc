// SPDX-License-Identifier: GPL-3.0-or-later

/**
 * @file
 * What one crack event costs (fracture issue, "must be fast"): the
 * rebuild and state transfer of Simulator::crack_edges() and the solve of
 * the next step on the cracked mesh, against one plain step with
 * factorization, on a square block of about 1e4 and 1e5 cells (P1, DDA,
 * gravity, bottom edge fixed; fracture on, with strengths too high for
 * any edge to fail by itself).
 *
 * Measured per size:
 * - first step: Simulator::do_time_step() after setup() (element matrices,
 *   assembly, factorization, solve): the "plain solve";
 * - steady step: the next step (factorization reused);
 * - crack: crack_edges() of the interior edge nearest the centre (node
 *   splitting, new triangulation, dofs, element matrices, sparsity,
 *   constraints, contacts, state transfer);
 * - step after the crack: the next do_time_step() (new factorization, the
 *   crack faces' contacts).
 * The goal: crack + step after it within two plain solves.
 *
 * Every first step is measured warm: a throwaway scene of the largest
 * size is solved first.
 *
 * Three cracks per size:
 * - one edge: both its ends stay single, so the crack is only marked
 *   (closed, thesis figure 5.4) and the step after has no crack faces in
 *   contact;
 * - two edges through the centre: their middle vertex splits, the crack is
 *   open between two tips inside the block, and the step after iterates
 *   the crack faces' contacts (open-close iteration);
 * - the same two edges with `Fracture/Tip mesh size` = h / 4 (issue 18):
 *   crack_edges() also refines the cells around both tips to a quarter of
 *   the mesh size (growth rate 1.3), in the same rebuild, and carries the
 *   state to them; the step after runs on the refined mesh.
 * After each step after the crack, the deal.II-style timer table of the
 * run goes to stderr with NDDA_TIMER_TABLE=1.
 *
 * Usage: crack_event [target n_cells ...]   (default: 1e4 1e5)
 */

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <ndda/fracture/edge_stress.h>
#include <ndda/parameters/parameters.h>
#include <ndda/simulator.h>

#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

namespace
{
  std::string
  scene(const double mesh_size, const double tip_mesh_size = 0)
  {
    return R"(
subsection Fracture
  set Tip mesh size = )" +
           std::to_string(tip_mesh_size) + R"(
end

subsection Control
  set Analysis type   = dynamic
  set Time integrator = DDA
  set Time step       = 1e-4
  set End time        = 1
end
subsection Materials
  set Names = rock
  subsection rock
    set Density          = 2600
    set Young's modulus  = 50e9
    set Poisson's ratio  = 0.25
    set Cohesion         = 1e20
    set Tensile strength = 1e20
    set Fracture         = true
  end
end
subsection Geometry
  set Blocks = block
  subsection block
    set Outer boundary = 0, 0; 1, 0; 1, 1; 0, 1
    set Material  = rock
    set Mesh size = )" +
           std::to_string(mesh_size) + R"(
  end
end
subsection Loads
  set Gravity = 0; -9.81
end
subsection Boundary conditions
  set Names = base
  subsection base
    set Type     = fixed
    set Segments = 0, 0, 1, 0
  end
end
)";
  }
} // namespace

int
main(int argc, char **argv)
{
  using namespace dealii;
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::vector<double>              targets;
  for (int i = 1; i < argc; ++i)
    targets.push_back(std::stod(argv[i]));
  if (targets.empty())
    targets = {1e4, 1e5};

  std::cout << "cells, first step (s), steady step (s), crack (s), "
               "step after crack (s) (its factorizations), (crack + step "
               "after) / first step"
            << std::endl;
  // The first solve of a process pays for touching fresh memory (page
  // faults, UMFPACK's workspace): a throwaway scene of the largest size
  // first, so that every "first step" below is measured warm.
  {
    ParameterHandler             prm;
    ndda::parameters::Parameters parameters;
    parameters.read(scene(std::sqrt(5. / targets.back())), "warm_up.prm", prm);
    parameters.output.interval = 0;
    ndda::Simulator<2> simulator(parameters);
    simulator.setup();
    simulator.do_time_step();
  }
  enum class Crack
  {
    one_edge,
    two_edges,
    refined
  };
  for (const Crack kind : {Crack::one_edge, Crack::two_edges, Crack::refined})
    for (const double target : targets)
      {
        const bool refined = kind == Crack::refined;
        // The mesher gives about 5 / h^2 triangles on the unit square.
        const double                 h = std::sqrt(5. / target);
        ParameterHandler             prm;
        ndda::parameters::Parameters parameters;
        parameters.read(scene(h, refined ? h / 4 : 0.), "crack_event.prm", prm);
        parameters.output.interval = 0;
        ndda::Simulator<2> simulator(parameters);
        simulator.setup();
        const auto &mesh = simulator.get_mesh().get_block_mesh();

        Timer timer;
        simulator.do_time_step();
        const double first = timer.wall_time();
        timer.restart();
        simulator.do_time_step();
        const double steady = timer.wall_time();

        // The interior edge nearest the centre; for two edges, also the
        // interior edge from its second end that continues it most
        // straight.
        const auto edges =
          ndda::fracture::find_interior_edges(mesh.triangles,
                                              mesh.vertices.size());
        const auto direction = [&](const unsigned int a, const unsigned int b) {
          return (mesh.vertices[b] - mesh.vertices[a]) /
                 mesh.vertices[b].distance(mesh.vertices[a]);
        };
        std::array<unsigned int, 2> chosen{};
        double                      best = 1e9;
        for (const auto &e : edges)
          {
            const Point<2> mid = 0.5 * (mesh.vertices[e.vertices[0]] +
                                        mesh.vertices[e.vertices[1]]);
            if (mid.distance(Point<2>(0.5, 0.5)) < best)
              {
                best   = mid.distance(Point<2>(0.5, 0.5));
                chosen = e.vertices;
              }
          }
        std::vector<std::array<unsigned int, 2>> crack = {chosen};
        if (kind != Crack::one_edge)
          {
            std::array<unsigned int, 2> next{};
            double                      straightest = -2;
            for (const auto &e : edges)
              for (unsigned int k = 0; k < 2; ++k)
                if (e.vertices[k] == chosen[1] &&
                    e.vertices[1 - k] != chosen[0])
                  {
                    const double cosine =
                      direction(chosen[0], chosen[1]) *
                      direction(chosen[1], e.vertices[1 - k]);
                    if (cosine > straightest)
                      {
                        straightest = cosine;
                        next        = e.vertices;
                      }
                  }
            crack.push_back(next);
          }
        const unsigned int n_cells = mesh.triangles.size();
        timer.restart();
        simulator.crack_edges(crack);
        const double       crack_time     = timer.wall_time();
        const unsigned int n_after        = mesh.triangles.size();
        const unsigned int factorizations = simulator.n_factorizations();
        timer.restart();
        simulator.do_time_step();
        const double       after = timer.wall_time();
        const unsigned int after_factorizations =
          simulator.n_factorizations() - factorizations;
        const double ratio = (crack_time + after) / first;
        if (std::getenv("NDDA_TIMER_TABLE") != nullptr)
          simulator.get_timer().print_summary(std::cerr);
        std::cout << n_cells << (kind == Crack::one_edge ? "" : ", two edges")
                  << (refined ? ", refined to " + std::to_string(n_after) : "")
                  << ", " << first << ", " << steady << ", " << crack_time
                  << ", " << after << " (" << after_factorizations
                  << " factorizations), " << ratio << std::endl;
        // For doc/validation.md (scripts/validation_page.py).
        const std::string key =
          std::string("crack_event.") +
          (kind == Crack::two_edges ? "open." :
           refined                  ? "refined." :
                                      "") +
          std::to_string(int(std::round(std::log10(target)))) + ".";
        std::cout << std::setprecision(3) << "@value " << key << "cells "
                  << n_cells << "\n@value " << key << "crack_ms "
                  << 1e3 * crack_time << "\n@value " << key << "ratio " << ratio
                  << "\n@value " << key << "met "
                  << (ratio <= 2 ? "met" : "**NOT met**")
                  << std::setprecision(6) << std::endl;
      }
}
