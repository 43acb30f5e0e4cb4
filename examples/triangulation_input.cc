// SPDX-License-Identifier: GPL-3.0-or-later
//
// Using ndda as a library with your own deal.II mesh.
//
// A user who already has a Triangulation<2> of triangles hands it to
// Simulator instead of a Geometry section: every connected group of cells
// with the same material id becomes one block, and vertices on the
// interface between two material ids are split, so that the blocks become
// separate bodies (DESIGN.md: blocks never share vertices).
//
// Here a rectangle made of triangles carries two material ids: the left
// half (id 0) is clamped at its left edge, the right half (id 1) is a
// separate block that falls under gravity. After 0.2 s the free block must
// have fallen g t^2 / 2 while the clamped one sags only elastically.

#include <deal.II/base/mpi.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <ndda/parameters/parameters.h>
#include <ndda/simulator.h>

#include <cmath>
#include <iostream>

int
main(int argc, char **argv)
{
  using namespace dealii;
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  try
    {
      // 1. Any deal.II triangulation of triangles.
      Triangulation<2> triangulation;
      GridGenerator::subdivided_hyper_rectangle_with_simplices(
        triangulation, {8, 2}, Point<2>(0, 0), Point<2>(2, 0.5));
      for (const auto &cell : triangulation.active_cell_iterators())
        cell->set_material_id(cell->center()[0] < 1 ? 0 : 1);

      // 2. The rest of the scene as a .prm text (or a file): no Geometry
      //    section. The material ids of the mesh index Materials/Names.
      const std::string            scene = R"(
        set Scene name = triangulation_input
        subsection Control
          set Time step = 0.01
          set End time = 0.2
          set Maximum displacement ratio = 0.5
        end
        # The blocks touch along x = 1; with contact off, the right block
        # falls freely past the clamped one, which shows that they are
        # separate bodies.
        subsection Contact
          set Enable = false
        end
        subsection Materials
          set Names = left, right
          subsection left
            set Young's modulus = 1e9
          end
          subsection right
            set Young's modulus = 2e9
          end
        end
        subsection Loads
          set Gravity = 0; -9.81
        end
        subsection Boundary conditions
          set Names = clamp
          subsection clamp
            set Type = fixed
            set Segments = 0, 0, 0, 0.5
          end
        end
        subsection Output
          set Measure points = 1.5, 0.25
          set Interval = 0.1
        end
      )";
      ParameterHandler             prm;
      ndda::parameters::Parameters parameters;
      parameters.read(scene, "triangulation_input.prm", prm);

      // 3. Hand both to the simulator and run.
      ndda::Simulator<2> simulator(parameters, &triangulation);
      simulator.run();

      const unsigned int n_blocks = simulator.get_mesh().n_blocks();
      const double       fallen =
        -simulator.get_measure_histories()[0].back().displacement[1];
      const double exact = 0.5 * 9.81 * 0.2 * 0.2;
      std::cout << "blocks: " << n_blocks << ", free block fell " << fallen
                << " m (g t^2 / 2 = " << exact << " m)" << std::endl;
      if (n_blocks != 2 || std::abs(fallen - exact) > 1e-9 * exact)
        {
          std::cout << "FAILED" << std::endl;
          return 1;
        }
    }
  catch (const std::exception &exc)
    {
      std::cerr << exc.what() << std::endl;
      return 1;
    }
  return 0;
}
