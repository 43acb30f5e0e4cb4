// SPDX-License-Identifier: GPL-3.0-or-later
//
// Throughput of mesh_scene(): a rectangle meshed as one block, and a square
// region cut by a grid of joints (horizontal, vertical and one diagonal
// family, so that the blocks are triangles and quadrilaterals and the
// arrangement has intersection points that are not input points), each at
// about 1e4, 1e5 and 1e6 triangles. Prints one row per case: triangles,
// blocks, wall time, triangles per second and the peak resident set size
// of the process during that case (VmHWM from /proc/self/status, reset
// through /proc/self/clear_refs before every case where the kernel allows
// it).
//
// Usage: meshing_throughput [max_triangles]   (default 1e6)

#include <ndda/geometry/block_mesh.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <malloc.h>
#include <string>
#include <vector>

using namespace ndda::geometry;
using dealii::Point;

namespace
{
  /** Peak resident set size in MiB, or -1 if unknown. */
  double
  peak_rss_mib()
  {
    std::ifstream status("/proc/self/status");
    std::string   line;
    while (std::getline(status, line))
      if (line.rfind("VmHWM:", 0) == 0)
        return std::stod(line.substr(6)) / 1024.;
    return -1.;
  }


  /**
   * Give freed memory back to the system (glibc) and reset VmHWM to the
   * current RSS (Linux: write 5 to clear_refs), so that the next reading is
   * the peak of the next case alone.
   */
  void
  reset_peak_rss()
  {
    malloc_trim(0);
    std::ofstream clear_refs("/proc/self/clear_refs");
    if (clear_refs)
      clear_refs << "5" << std::flush;
  }


  SceneGeometry
  rectangle_scene(const unsigned int n_triangles)
  {
    SceneGeometry    scene;
    BlockDescription block;
    block.name           = "rectangle";
    block.outer          = {Point<2>(0, 0),
                            Point<2>(4, 0),
                            Point<2>(4, 1),
                            Point<2>(0, 1)};
    block.target_n_cells = n_triangles;
    scene.blocks.push_back(block);
    return scene;
  }


  /**
   * The square [0,10]^2 cut by 9 horizontal, 9 vertical and 9 diagonal
   * joints that reach beyond it; the mesh size is chosen for about
   * n_triangles triangles in total (the same rule as for target_n_cells).
   */
  SceneGeometry
  jointed_scene(const unsigned int n_triangles)
  {
    SceneGeometry     scene;
    RegionDescription region;
    region.name  = "jointed";
    region.outer = {Point<2>(0, 0),
                    Point<2>(10, 0),
                    Point<2>(10, 10),
                    Point<2>(0, 10)};
    for (unsigned int i = 1; i < 10; ++i)
      {
        region.joints.push_back({Point<2>(-1, i), Point<2>(11, i)});
        region.joints.push_back({Point<2>(i + 0.5, -1), Point<2>(i + 0.5, 11)});
        region.joints.push_back(
          {Point<2>(-1, 2. * i - 11. - 1.), Point<2>(11, 2. * i - 11. + 11.)});
      }
    const double area = 100.;
    region.mesh_size =
      1.47 * std::sqrt(4. * area / (std::sqrt(3.) * double(n_triangles)));
    scene.regions.push_back(region);
    return scene;
  }


  void
  run(const std::string &name, const SceneGeometry &scene)
  {
    reset_peak_rss();
    const auto      start = std::chrono::steady_clock::now();
    const BlockMesh mesh  = mesh_scene(scene);
    const double    seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
        .count();
    std::cout << std::setw(10) << std::left << name << std::right
              << std::setw(10) << mesh.triangles.size() << std::setw(8)
              << mesh.block_names.size() << std::fixed << std::setprecision(3)
              << std::setw(10) << seconds << std::setprecision(0)
              << std::setw(12) << mesh.triangles.size() / seconds
              << std::setprecision(1) << std::setw(12) << peak_rss_mib()
              << std::defaultfloat << std::endl;
  }
} // namespace



int
main(int argc, char **argv)
{
  const double max_triangles = argc > 1 ? std::atof(argv[1]) : 1e6;

  std::cout << std::setw(10) << std::left << "case" << std::right
            << std::setw(10) << "triangles" << std::setw(8) << "blocks"
            << std::setw(10) << "wall (s)" << std::setw(12) << "triangles/s"
            << std::setw(12) << "peak (MiB)" << std::endl;
  for (const double n : {1e4, 1e5, 1e6})
    if (n <= max_triangles)
      {
        run("rectangle", rectangle_scene(n));
        run("jointed", jointed_scene(n));
      }
  return 0;
}
