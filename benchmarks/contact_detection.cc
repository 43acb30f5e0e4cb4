// SPDX-License-Identifier: GPL-3.0-or-later
//
// Scaling of contact detection: a grid of m x m unit square blocks (each two
// triangles and four boundary edges) with gaps of 0.01 between neighbours
// and a detection threshold of 0.02, so that every square touches its eight
// neighbours. For about 1e4, 1e5 and 1e6 boundary edges the program prints
// the number of edges n, the number of candidates, the wall time of
// boundary_edges() and of detect() (best of three runs below 1e6 edges),
// detect()'s time / (n log2 n), and the growth of detect()'s time from the
// previous size, next to the growth of n log2 n.
//
// Then a time stepping of the 1e4- and 1e5-edge grids: 50 steps in which
// every vertex moves by a random amount of up to 1e-4 in each direction
// (about the wall's motion per step against its detection distance), and
// every step calls detect() and a contact::NeighbourList's detect(), in
// turns (which one goes first alternates). It prints the mean time of
// each per step, their ratio, the list's builds, the (vertex, edge) pairs
// the list tests every step and the candidates of the last step.
//
// Usage: contact_detection [max_edges]   (default 1e6)

#include <ndda/contact/contact_detection.h>
#include <ndda/geometry/block_mesh.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <random>
#include <vector>

using namespace ndda;

namespace
{
  /** m x m unit squares, each its own block, @p gap apart. */
  geometry::BlockMesh
  square_grid(const unsigned int m, const double gap)
  {
    geometry::BlockMesh mesh;
    mesh.vertices.reserve(4 * m * m);
    mesh.triangles.reserve(2 * m * m);
    mesh.cell_block.reserve(2 * m * m);
    for (unsigned int j = 0; j < m; ++j)
      for (unsigned int i = 0; i < m; ++i)
        {
          const double       x = i * (1. + gap);
          const double       y = j * (1. + gap);
          const unsigned int n = mesh.vertices.size();
          const unsigned int b = i + m * j;
          mesh.vertices.emplace_back(x, y);
          mesh.vertices.emplace_back(x + 1., y);
          mesh.vertices.emplace_back(x + 1., y + 1.);
          mesh.vertices.emplace_back(x, y + 1.);
          mesh.triangles.push_back({{n, n + 1, n + 2}});
          mesh.triangles.push_back({{n, n + 2, n + 3}});
          mesh.cell_block.push_back(b);
          mesh.cell_block.push_back(b);
        }
    mesh.cell_material.assign(mesh.triangles.size(), 0);
    return mesh;
  }


  double
  seconds_since(const std::chrono::steady_clock::time_point start)
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                         start)
      .count();
  }


  /** detect() against a NeighbourList over @p n_steps steps of motion. */
  void
  time_stepping(const double       n_edges,
                const double       gap,
                const double       threshold,
                const unsigned int n_steps)
  {
    const unsigned int m =
      static_cast<unsigned int>(std::lround(std::sqrt(n_edges / 4.)));
    auto                                   mesh  = square_grid(m, gap);
    const auto                             edges = boundary_edges(mesh);
    std::mt19937                           random(1);
    std::uniform_real_distribution<double> motion(-1e-4, 1e-4);
    contact::NeighbourList                 list;
    double                                 fresh_time = 0, list_time = 0;
    bool                                   same         = true;
    std::size_t                            n_candidates = 0;
    for (unsigned int step = 0; step < n_steps; ++step)
      {
        for (auto &v : mesh.vertices)
          v += dealii::Tensor<1, 2>({motion(random), motion(random)});
        std::vector<contact::Candidate> fresh, listed;
        for (unsigned int turn = 0; turn < 2; ++turn)
          {
            const auto start = std::chrono::steady_clock::now();
            if ((turn + step) % 2 == 0)
              {
                fresh = contact::detect(mesh.vertices, edges, threshold);
                fresh_time += seconds_since(start);
              }
            else
              {
                listed = list.detect(mesh.vertices, edges, threshold);
                list_time += seconds_since(start);
              }
          }
        same         = same && fresh.size() == listed.size();
        n_candidates = listed.size();
      }
    std::cout << std::setw(9) << edges.size() << std::setw(14)
              << std::setprecision(4) << 1e3 * fresh_time / n_steps
              << std::setw(14) << 1e3 * list_time / n_steps << std::setw(10)
              << fresh_time / list_time << std::setw(9) << list.n_builds()
              << std::setw(10) << list.size() << std::setw(12) << n_candidates
              << std::setw(7) << (same ? "yes" : "NO") << std::endl;
  }
} // namespace


int
main(int argc, char **argv)
{
  const double max_edges = (argc > 1 ? std::atof(argv[1]) : 1e6);
  const double gap       = 0.01;
  const double threshold = 0.02;

  std::cout << std::setw(9) << "n_edges" << std::setw(12) << "candidates"
            << std::setw(14) << "boundary[s]" << std::setw(12) << "detect[s]"
            << std::setw(18) << "t/(n log2 n)[ns]" << std::setw(12) << "growth"
            << std::setw(16) << "n log2 n growth" << std::endl;

  double previous_time = 0., previous_nlogn = 0.;
  for (const double target : {1e4, 1e5, 1e6})
    {
      if (target > max_edges)
        break;
      const unsigned int m =
        static_cast<unsigned int>(std::lround(std::sqrt(target / 4.)));
      const auto mesh = square_grid(m, gap);

      auto         start         = std::chrono::steady_clock::now();
      const auto   edges         = boundary_edges(mesh);
      const double boundary_time = seconds_since(start);

      const unsigned int              repeats = (target < 1e6 ? 3 : 1);
      double                          time    = 1e300;
      std::vector<contact::Candidate> candidates;
      for (unsigned int r = 0; r < repeats; ++r)
        {
          start      = std::chrono::steady_clock::now();
          candidates = contact::detect(mesh.vertices, edges, threshold);
          time       = std::min(time, seconds_since(start));
        }

      const double n     = edges.size();
      const double nlogn = n * std::log2(n);
      std::cout << std::setw(9) << edges.size() << std::setw(12)
                << candidates.size() << std::setw(14) << std::setprecision(4)
                << boundary_time << std::setw(12) << time << std::setw(18)
                << 1e9 * time / nlogn << std::setw(12);
      if (previous_time > 0.)
        std::cout << time / previous_time << std::setw(16)
                  << nlogn / previous_nlogn;
      else
        std::cout << "-" << std::setw(16) << "-";
      std::cout << std::endl;
      previous_time  = time;
      previous_nlogn = nlogn;
    }

  std::cout << "\n50 steps of motion (up to 1e-4 per step and direction)\n"
            << std::setw(9) << "n_edges" << std::setw(14) << "detect[ms]"
            << std::setw(14) << "list[ms]" << std::setw(10) << "ratio"
            << std::setw(9) << "builds" << std::setw(10) << "pairs"
            << std::setw(12) << "candidates" << std::setw(7) << "same"
            << std::endl;
  for (const double target : {1e4, 1e5})
    if (target <= max_edges)
      time_stepping(target, gap, threshold, 50);
  return 0;
}
