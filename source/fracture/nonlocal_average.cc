// SPDX-License-Identifier: GPL-3.0-or-later
//
// The nonlocal edge stress: a bell-shaped weighted mean of the cell
// stresses within a material radius, doc/fracture.md "Nonlocal edge
// stress".

#include <deal.II/base/exceptions.h>

#include <ndda/fracture/nonlocal_average.h>

#include <algorithm>
#include <cmath>
#include <iterator>

namespace ndda
{
  namespace fracture
  {
    using namespace dealii;

    void
    NonlocalAverage::setup(
      const std::vector<InteriorEdge>                &edges,
      const std::vector<InteriorEdge>                &passable,
      const std::vector<Point<2>>                    &vertices,
      const std::vector<std::array<unsigned int, 3>> &triangles,
      const double                                    radius)
    {
      AssertThrow(radius > 0.,
                  ExcMessage("NonlocalAverage: the radius must be positive."));
      const unsigned int    n_cells = triangles.size();
      std::vector<Point<2>> centroid(n_cells);
      std::vector<double>   area(n_cells);
      for (unsigned int c = 0; c < n_cells; ++c)
        {
          const auto &t = triangles[c];
          centroid[c] =
            Point<2>((vertices[t[0]] + vertices[t[1]] + vertices[t[2]]) / 3.);
          const Tensor<1, 2> u = vertices[t[1]] - vertices[t[0]];
          const Tensor<1, 2> v = vertices[t[2]] - vertices[t[0]];
          area[c]              = 0.5 * std::abs(u[0] * v[1] - u[1] * v[0]);
        }

      // Neighbours of each cell through the passable edges (compressed).
      std::vector<unsigned int> neighbour_start(n_cells + 1, 0);
      for (const auto &edge : passable)
        for (const unsigned int c : edge.cells)
          {
            AssertIndexRange(c, n_cells);
            ++neighbour_start[c + 1];
          }
      for (unsigned int c = 0; c < n_cells; ++c)
        neighbour_start[c + 1] += neighbour_start[c];
      std::vector<unsigned int> neighbours(neighbour_start[n_cells]);
      {
        std::vector<unsigned int> fill(neighbour_start.begin(),
                                       neighbour_start.end() - 1);
        for (const auto &edge : passable)
          {
            neighbours[fill[edge.cells[0]]++] = edge.cells[1];
            neighbours[fill[edge.cells[1]]++] = edge.cells[0];
          }
      }

      // Cell pairs, smaller cell first: an edge's and a passage's name
      // that a crack does not change.
      const auto pair_of = [](const InteriorEdge &edge) {
        return std::array<unsigned int, 2>{
          {std::min(edge.cells[0], edge.cells[1]),
           std::max(edge.cells[0], edge.cells[1])}};
      };
      std::vector<std::array<unsigned int, 2>> now_passable;
      now_passable.reserve(passable.size());
      for (const auto &edge : passable)
        now_passable.push_back(pair_of(edge));
      std::sort(now_passable.begin(), now_passable.end());

      // Rows that may be kept: same cells and radius as last time, and no
      // passage opened or closed near the edge. The centroids of the
      // cells of every changed passage; a row is recomputed if one lies
      // within the disc (the search crosses a passage only if both its
      // cells' centroids do). Vertices must be where they were last time
      // (EdgeFailureCheck passes the initial geometry).
      const bool may_keep =
        last_radius == radius && last_n_cells == n_cells && !row_cells.empty();
      std::vector<Point<2>> changed;
      if (may_keep)
        {
          std::vector<std::array<unsigned int, 2>> difference;
          std::set_symmetric_difference(passable_cells.begin(),
                                        passable_cells.end(),
                                        now_passable.begin(),
                                        now_passable.end(),
                                        std::back_inserter(difference));
          for (const auto &pair : difference)
            for (const unsigned int c : pair)
              changed.push_back(centroid[c]);
          for (unsigned int c = 0; c < n_cells; ++c)
            if (centroid[c] != last_centroid[c])
              {
                changed.push_back(centroid[c]);
                changed.push_back(last_centroid[c]);
              }
        }
      std::vector<unsigned int> old_row_order(row_cells.size());
      for (unsigned int r = 0; r < old_row_order.size(); ++r)
        old_row_order[r] = r;
      std::sort(old_row_order.begin(),
                old_row_order.end(),
                [&](const unsigned int a, const unsigned int b) {
                  return row_cells[a] < row_cells[b];
                });
      const auto old_offsets = std::move(offsets);
      const auto old_cells   = std::move(cells);
      const auto old_weights = std::move(weights);

      const double radius_2 = radius * radius;
      offsets.assign(1, 0);
      cells.clear();
      weights.clear();
      std::vector<std::array<unsigned int, 2>> now_rows(edges.size());
      n_computed = 0;
      // Breadth-first search from the edge's two cells over the cells whose
      // centroid lies in the disc; `seen` holds the edge that last visited
      // a cell, so it is never cleared.
      std::vector<unsigned int> seen(n_cells, numbers::invalid_unsigned_int);
      std::vector<unsigned int> queue;
      for (unsigned int e = 0; e < edges.size(); ++e)
        {
          const auto    &edge = edges[e];
          const Point<2> x(
            0.5 * (vertices[edge.vertices[0]] + vertices[edge.vertices[1]]));
          now_rows[e] = pair_of(edge);
          if (may_keep && std::none_of(changed.begin(),
                                       changed.end(),
                                       [&](const Point<2> &p) {
                                         return p.distance_square(x) <=
                                                radius_2;
                                       }))
            {
              const auto found =
                std::lower_bound(old_row_order.begin(),
                                 old_row_order.end(),
                                 now_rows[e],
                                 [&](const unsigned int                 r,
                                     const std::array<unsigned int, 2> &key) {
                                   return row_cells[r] < key;
                                 });
              if (found != old_row_order.end() &&
                  row_cells[*found] == now_rows[e])
                {
                  cells.insert(cells.end(),
                               old_cells.begin() + old_offsets[*found],
                               old_cells.begin() + old_offsets[*found + 1]);
                  weights.insert(weights.end(),
                                 old_weights.begin() + old_offsets[*found],
                                 old_weights.begin() + old_offsets[*found + 1]);
                  offsets.push_back(cells.size());
                  continue;
                }
            }
          ++n_computed;
          const auto weight = [&](const unsigned int c) {
            const double q = 1. - centroid[c].distance_square(x) / radius_2;
            return q > 0. ? area[c] * q * q : 0.;
          };
          const std::size_t row_start = cells.size();
          queue.clear();
          for (const unsigned int c : edge.cells)
            if (seen[c] != e && weight(c) > 0.)
              {
                seen[c] = e;
                queue.push_back(c);
              }
          for (std::size_t i = 0; i < queue.size(); ++i)
            {
              const unsigned int c = queue[i];
              cells.push_back(c);
              weights.push_back(weight(c));
              for (unsigned int k = neighbour_start[c];
                   k < neighbour_start[c + 1];
                   ++k)
                {
                  const unsigned int n = neighbours[k];
                  if (seen[n] != e && weight(n) > 0.)
                    {
                      seen[n] = e;
                      queue.push_back(n);
                    }
                }
            }
          if (cells.size() == row_start)
            // Both cells outside the disc: the cell average.
            for (const unsigned int c : edge.cells)
              {
                cells.push_back(c);
                weights.push_back(1.);
              }
          double sum = 0;
          for (std::size_t k = row_start; k < cells.size(); ++k)
            sum += weights[k];
          for (std::size_t k = row_start; k < cells.size(); ++k)
            weights[k] /= sum;
          offsets.push_back(cells.size());
        }
      row_cells      = std::move(now_rows);
      passable_cells = std::move(now_passable);
      last_centroid  = centroid;
      last_radius    = radius;
      last_n_cells   = n_cells;
    }



    std::vector<SymmetricTensor<2, 2>>
    NonlocalAverage::apply(
      const std::vector<SymmetricTensor<2, 2>> &cell_stresses) const
    {
      std::vector<SymmetricTensor<2, 2>> result(offsets.size() - 1);
      for (unsigned int e = 0; e + 1 < offsets.size(); ++e)
        for (unsigned int k = offsets[e]; k < offsets[e + 1]; ++k)
          {
            AssertIndexRange(cells[k], cell_stresses.size());
            result[e] += weights[k] * cell_stresses[cells[k]];
          }
      return result;
    }



    double
    NonlocalAverage::mean_cells_per_edge() const
    {
      return offsets.size() > 1 ?
               static_cast<double>(cells.size()) / (offsets.size() - 1) :
               0.;
    }
  } // namespace fracture
} // namespace ndda
