// SPDX-License-Identifier: GPL-3.0-or-later
//
// The nonlocal edge stress (fracture::NonlocalAverage, doc/fracture.md
// "Nonlocal average"): the weighted mean written out on a small mesh, a
// constant stress kept, the cell average below the cells' size, closed
// cracks and other blocks not crossed, and the rows kept after a crack
// equal to a fresh setup's.

#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>

#include <ndda/fracture/edge_stress.h>
#include <ndda/fracture/nonlocal_average.h>

#include <cmath>
#include <iostream>

#include "tests.h"

using namespace dealii;
using namespace ndda::fracture;
using ndda_tests::check;
using ndda_tests::check_value;

namespace
{
  SymmetricTensor<2, 2>
  tensor(const double xx, const double yy, const double xy)
  {
    SymmetricTensor<2, 2> t;
    t[0][0] = xx;
    t[1][1] = yy;
    t[0][1] = xy;
    return t;
  }

  /** Check two tensors within 1e-12 of @p scale (their difference norm). */
  void
  check_tensor(const std::string           &what,
               const SymmetricTensor<2, 2> &measured,
               const SymmetricTensor<2, 2> &expected,
               const double                 scale)
  {
    check_value(what, (measured - expected).norm(), 0., scale);
  }


  void
  test_nonlocal_average()
  {
    std::cout << "Nonlocal edge stress" << std::endl;
    const double s = 1e6;
    // test_edge_stresses()'s mesh: block 1 the unit square in four
    // triangles around (0.3, 0.6), block 2 one triangle on its own
    // vertices, with a stress far from the others.
    const std::vector<Point<2>> vertices = {
      {0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.3, 0.6}, {1, 0}, {2, 0}, {1, 1}};
    const std::vector<std::array<unsigned int, 3>> triangles = {
      {{0, 1, 4}}, {{1, 2, 4}}, {{2, 3, 4}}, {{3, 0, 4}}, {{5, 6, 7}}};
    const std::vector<SymmetricTensor<2, 2>> cell_stress = {
      tensor(1 * s, -2 * s, 0.5 * s),
      tensor(3 * s, 1 * s, -1 * s),
      tensor(-2 * s, 4 * s, 2 * s),
      tensor(0.5 * s, 0.25 * s, -0.75 * s),
      tensor(100 * s, 100 * s, 100 * s)};
    const std::vector<double>       areas = {0.3, 0.35, 0.2, 0.15, 0.5};
    const std::vector<InteriorEdge> edges =
      find_interior_edges(triangles, vertices.size());

    // The weighted mean over the cells @p of, written out.
    const auto expected = [&](const InteriorEdge              &edge,
                              const std::vector<unsigned int> &of,
                              const double                     radius) {
      const Point<2>        x = 0.5 * (vertices[edge.vertices[0]] +
                                Tensor<1, 2>(vertices[edge.vertices[1]]));
      SymmetricTensor<2, 2> sum;
      double                weight_sum = 0;
      for (const unsigned int c : of)
        {
          const auto    &t = triangles[c];
          const Point<2> centroid =
            (vertices[t[0]] + Tensor<1, 2>(vertices[t[1]]) +
             Tensor<1, 2>(vertices[t[2]])) /
            3.;
          const double q = 1 - centroid.distance_square(x) / (radius * radius);
          if (q <= 0)
            continue;
          sum += areas[c] * q * q * cell_stress[c];
          weight_sum += areas[c] * q * q;
        }
      return SymmetricTensor<2, 2>(sum / weight_sum);
    };

    // A radius over the whole block: every cell of block 1, none of
    // block 2 (no passable edge leads there).
    NonlocalAverage average;
    average.setup(edges, edges, vertices, triangles, 1.5);
    auto result = average.apply(cell_stress);
    for (unsigned int e = 0; e < edges.size(); ++e)
      check_tensor("R = 1.5, edge " + std::to_string(e),
                   result[e],
                   expected(edges[e], {0, 1, 2, 3}, 1.5),
                   s);
    check(std::abs(average.mean_cells_per_edge() - 4) < 1e-12,
          "R = 1.5: four cells per edge");

    // A constant stress is kept, at any radius.
    for (const double radius : {0.01, 0.4, 1.5})
      {
        average.setup(edges, edges, vertices, triangles, radius);
        const auto constant = average.apply(
          std::vector<SymmetricTensor<2, 2>>(5, tensor(2 * s, -s, 3 * s)));
        for (unsigned int e = 0; e < edges.size(); ++e)
          check_tensor("constant stress, R = " + std::to_string(radius),
                       constant[e],
                       tensor(2 * s, -s, 3 * s),
                       s);
      }

    // A radius below every centroid distance: the cell average.
    average.setup(edges, edges, vertices, triangles, 0.01);
    result                = average.apply(cell_stress);
    const auto cell_means = cell_average_edge_stresses(edges, cell_stress);
    for (unsigned int e = 0; e < edges.size(); ++e)
      check_tensor("R = 0.01 (cell average), edge " + std::to_string(e),
                   result[e],
                   cell_means[e],
                   s);

    // Edges (1,4) and (3,4) closed cracks: from edge (0,4) (cells 3 and 0)
    // the average cannot reach cells 1 and 2, whichever the radius.
    average.setup(edges, {edges[0], edges[2]}, vertices, triangles, 1.5);
    result = average.apply(cell_stress);
    check_tensor("cracks at (1,4) and (3,4): edge (0,4)",
                 result[0],
                 expected(edges[0], {0, 3}, 1.5),
                 s);
    check_tensor("cracks at (1,4) and (3,4): edge (2,4)",
                 result[2],
                 expected(edges[2], {1, 2}, 1.5),
                 s);
    // A middle radius: only the cells whose centroid is in the disc.
    average.setup(edges, edges, vertices, triangles, 0.6);
    result = average.apply(cell_stress);
    for (unsigned int e = 0; e < edges.size(); ++e)
      check_tensor("R = 0.6, edge " + std::to_string(e),
                   result[e],
                   expected(edges[e], {0, 1, 2, 3}, 0.6),
                   s);
    std::cout << "  R = 0.6: " << average.mean_cells_per_edge()
              << " cells per edge" << std::endl;
    check(average.mean_cells_per_edge() > 2 &&
            average.mean_cells_per_edge() < 4,
          "R = 0.6: some edges reach beyond their own two cells, not all "
          "reach all four");

    // After a crack: a setup on the same cells keeps the rows far from
    // the closed passages and gives what a fresh setup gives. A 20 x 20
    // grid of squares on the unit square, two triangles each; a crack
    // closes the passages of two edges near the corner (0, 0).
    const unsigned int                       n = 20;
    std::vector<Point<2>>                    grid;
    std::vector<std::array<unsigned int, 3>> grid_cells;
    for (unsigned int j = 0; j <= n; ++j)
      for (unsigned int i = 0; i <= n; ++i)
        grid.emplace_back(1. * i / n, 1. * j / n);
    for (unsigned int j = 0; j < n; ++j)
      for (unsigned int i = 0; i < n; ++i)
        {
          const unsigned int v = j * (n + 1) + i;
          grid_cells.push_back({{v, v + 1, v + n + 2}});
          grid_cells.push_back({{v, v + n + 2, v + n + 1}});
        }
    std::vector<SymmetricTensor<2, 2>> grid_stress;
    for (unsigned int c = 0; c < grid_cells.size(); ++c)
      grid_stress.push_back(
        tensor(std::sin(0.1 * c) * s, std::cos(0.37 * c) * s, 0.01 * c * s));
    const auto grid_edges = find_interior_edges(grid_cells, grid.size());
    std::vector<InteriorEdge> cracked_passable;
    for (const auto &edge : grid_edges)
      if (std::max(grid[edge.vertices[0]][0], grid[edge.vertices[1]][0]) >
            0.11 ||
          std::max(grid[edge.vertices[0]][1], grid[edge.vertices[1]][1]) >
            0.06 ||
          std::abs(grid[edge.vertices[0]][1] - grid[edge.vertices[1]][1]) >
            1e-12)
        cracked_passable.push_back(edge);
    check(cracked_passable.size() + 2 == grid_edges.size(),
          "the crack closes two passages");
    NonlocalAverage kept, fresh;
    kept.setup(grid_edges, grid_edges, grid, grid_cells, 0.15);
    kept.setup(grid_edges, cracked_passable, grid, grid_cells, 0.15);
    fresh.setup(grid_edges, cracked_passable, grid, grid_cells, 0.15);
    const auto kept_stress  = kept.apply(grid_stress);
    const auto fresh_stress = fresh.apply(grid_stress);
    double     difference   = 0;
    for (unsigned int e = 0; e < grid_edges.size(); ++e)
      difference =
        std::max(difference, (kept_stress[e] - fresh_stress[e]).norm());
    std::cout << "  after a crack: " << kept.n_computed_edges() << " of "
              << grid_edges.size()
              << " edges recomputed; largest difference to a fresh setup "
              << difference / s << " s" << std::endl;
    check(difference < 1e-12 * s, "kept rows equal a fresh setup's");
    check(kept.n_computed_edges() < grid_edges.size() / 4,
          "only the edges near the crack are recomputed");
    check(fresh.n_computed_edges() == grid_edges.size(),
          "a fresh setup computes every edge");
    bool            crack_matters = false;
    NonlocalAverage uncracked;
    uncracked.setup(grid_edges, grid_edges, grid, grid_cells, 0.15);
    const auto uncracked_stress = uncracked.apply(grid_stress);
    for (unsigned int e = 0; e < grid_edges.size(); ++e)
      crack_matters |=
        (uncracked_stress[e] - fresh_stress[e]).norm() > 1e-6 * s;
    check(crack_matters, "the crack changes the average near it");
  }

} // namespace

int
main()
{
  std::cout << std::setprecision(15);
  test_nonlocal_average();
  std::cout << "OK" << std::endl;
}
