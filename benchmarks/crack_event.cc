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
 * Usage: crack_event [target n_cells ...]   (default: 1e4 1e5)
 */

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <ndda/fracture/edge_stress.h>
#include <ndda/parameters/parameters.h>
#include <ndda/simulator.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

namespace
{
  std::string
  scene(const double mesh_size)
  {
    return R"(
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
               "step after crack (s), (crack + step after) / first step"
            << std::endl;
  for (const double target : targets)
    {
      // The mesher gives about 5 / h^2 triangles on the unit square.
      const double                 h = std::sqrt(5. / target);
      ParameterHandler             prm;
      ndda::parameters::Parameters parameters;
      parameters.read(scene(h), "crack_event.prm", prm);
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

      // The interior edge nearest the centre.
      const auto edges =
        ndda::fracture::find_interior_edges(mesh.triangles,
                                            mesh.vertices.size());
      std::array<unsigned int, 2> chosen{};
      double                      best = 1e9;
      for (const auto &e : edges)
        {
          const Point<2> mid =
            0.5 * (mesh.vertices[e.vertices[0]] + mesh.vertices[e.vertices[1]]);
          if (mid.distance(Point<2>(0.5, 0.5)) < best)
            {
              best   = mid.distance(Point<2>(0.5, 0.5));
              chosen = e.vertices;
            }
        }
      const unsigned int n_cells = mesh.triangles.size();
      timer.restart();
      simulator.crack_edges({chosen});
      const double crack = timer.wall_time();
      timer.restart();
      simulator.do_time_step();
      const double after = timer.wall_time();
      std::cout << n_cells << ", " << first << ", " << steady << ", " << crack
                << ", " << after << ", " << (crack + after) / first
                << std::endl;
      // For doc/validation.md (scripts/validation_page.py).
      const std::string key =
        "crack_event." + std::to_string(int(std::round(std::log10(target)))) +
        ".";
      std::cout << std::setprecision(3) << "@value " << key << "cells "
                << n_cells << "\n@value " << key << "crack_ms " << 1e3 * crack
                << "\n@value " << key << "ratio " << (crack + after) / first
                << "\n@value " << key << "met "
                << ((crack + after) / first <= 2 ? "met" : "**NOT met**")
                << std::setprecision(6) << std::endl;
    }
}
