// SPDX-License-Identifier: GPL-3.0-or-later
//
// A gmsh mesh whose physical surfaces share nodes must become separate
// blocks (deal.II's read_msh(filename) would glue them; ndda reads from a
// stream), with the materials given per physical tag; and XDMF/HDF5 output
// must be written when asked for.

#include <filesystem>
#include <string>
#include <vector>

#include "tests.h"

using namespace ndda_tests;

int
main(int argc, char **argv)
{
  using namespace dealii;
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  ndda::Simulator<2> simulator(std::string(NDDA_TEST_DIR) +
                               "/data/two_blocks.prm");
  simulator.run();
  const auto &mesh = simulator.get_mesh();
  std::cout << "blocks " << mesh.n_blocks() << ", cells "
            << mesh.get_triangulation().n_active_cells() << ", vertices "
            << mesh.get_triangulation().n_vertices() << std::endl;
  record("gmsh_and_hdf5.blocks", mesh.n_blocks());
  record("gmsh_and_hdf5.vertices", mesh.get_triangulation().n_vertices());
  check(mesh.n_blocks() == 2, "two blocks");
  check(mesh.get_triangulation().n_vertices() == 8,
        "the shared nodes must be split (8 vertices)");
  for (const auto &cell : mesh.get_triangulation().active_cell_iterators())
    check(cell->material_id() == (cell->center()[0] < 1 ? 0u : 1u),
          "material per physical tag");

  const double fallen =
    -simulator.get_measure_histories()[0].back().displacement[1];
  const double sag =
    -simulator.get_measure_histories()[1].back().displacement[1];
  std::cout << "right block fell " << fallen
            << " m (g t^2 / 2 = " << 0.5 * 9.81 * 0.01
            << "), clamped block sagged " << sag << " m" << std::endl;
  record("gmsh_and_hdf5.fall_error", std::abs(fallen - 0.5 * 9.81 * 0.01), 2);
  check(std::abs(fallen - 0.5 * 9.81 * 0.01) < 1e-9, "free fall");
  check(sag < 1e-3, "the clamped block holds");

  const std::vector<std::string> files     = {"solution.xdmf",
                                              "solution-00000.h5",
                                              "solution-00002.h5",
                                              "solution.pvd",
                                              "solution-00002.vtu",
                                              "statistics",
                                              "measure_points.txt",
                                              "parameters.prm",
                                              "log.txt"};
  unsigned int                   n_written = 0;
  for (const std::string &file : files)
    {
      const bool exists = std::filesystem::exists("output/two_blocks/" + file);
      std::cout << file << (exists ? " written" : " MISSING") << std::endl;
      n_written += exists ? 1 : 0;
    }
  record("gmsh_and_hdf5.files_asked", unsigned(files.size()));
  record("gmsh_and_hdf5.files_written", n_written);
  check(n_written == files.size(), "every output file written");
  std::cout << "OK" << std::endl;
}
