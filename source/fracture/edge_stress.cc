// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stresses on the interior edges of a triangle mesh, thesis 5.21-5.23 and
// the nodal variant; derivations in doc/fracture.md.

#include <deal.II/base/exceptions.h>

#include <ndda/fracture/edge_stress.h>

#include <algorithm>
#include <string>

namespace ndda
{
  namespace fracture
  {
    using namespace dealii;

    EdgeState
    edge_state(const SymmetricTensor<2, 2> &stress,
               const Point<2>              &a,
               const Point<2>              &b)
    {
      const Tensor<1, 2> edge   = b - a;
      const double       length = edge.norm();
      Assert(length > 0., ExcMessage("edge_state: the edge has zero length."));
      const Tensor<1, 2> t = edge / length;
      // The unit normal on the right of a -> b: t turned by -90 degrees.
      const Tensor<1, 2> n({t[1], -t[0]});
      const Tensor<1, 2> traction = stress * n;

      EdgeState state;
      state.stress        = stress;
      state.normal_stress = n * traction;
      state.shear_stress  = t * traction;
      return state;
    }



    std::vector<InteriorEdge>
    find_interior_edges(
      const std::vector<std::array<unsigned int, 3>> &triangles,
      const unsigned int                              n_vertices)
    {
      // Every side of every triangle, bucketed by its smaller vertex (a
      // counting sort): the sides that share a vertex pair then sit in the
      // same short bucket, and the result comes out ordered by vertex pair.
      struct Side
      {
        unsigned int other_vertex;
        unsigned int cell;
        bool         forward; // runs from the smaller to the larger vertex
      };
      std::vector<unsigned int> bucket_start(n_vertices + 1, 0);
      for (const auto &triangle : triangles)
        for (unsigned int k = 0; k < 3; ++k)
          {
            AssertIndexRange(triangle[k], n_vertices);
            ++bucket_start[std::min(triangle[k], triangle[(k + 1) % 3]) + 1];
          }
      for (unsigned int v = 0; v < n_vertices; ++v)
        bucket_start[v + 1] += bucket_start[v];

      std::vector<Side>         sides(bucket_start[n_vertices]);
      std::vector<unsigned int> fill(bucket_start.begin(),
                                     bucket_start.end() - 1);
      for (unsigned int c = 0; c < triangles.size(); ++c)
        for (unsigned int k = 0; k < 3; ++k)
          {
            const unsigned int from           = triangles[c][k];
            const unsigned int to             = triangles[c][(k + 1) % 3];
            sides[fill[std::min(from, to)]++] = {std::max(from, to),
                                                 c,
                                                 from < to};
          }

      std::vector<InteriorEdge> edges;
      edges.reserve(triangles.size() * 3 / 2);
      for (unsigned int v = 0; v < n_vertices; ++v)
        {
          const auto begin = sides.begin() + bucket_start[v];
          const auto end   = sides.begin() + bucket_start[v + 1];
          std::sort(begin, end, [](const Side &x, const Side &y) {
            return x.other_vertex < y.other_vertex;
          });
          for (auto first = begin; first != end;)
            {
              auto last = first + 1;
              while (last != end && last->other_vertex == first->other_vertex)
                ++last;
              const std::string where =
                "find_interior_edges: the edge (" + std::to_string(v) + ", " +
                std::to_string(first->other_vertex) + ")";
              AssertThrow(last - first <= 2,
                          ExcMessage(where + " belongs to " +
                                     std::to_string(last - first) +
                                     " triangles; at most two may share "
                                     "an edge."));
              if (last - first == 2)
                {
                  const Side &p = first[0];
                  const Side &q = first[1];
                  AssertThrow(p.forward != q.forward,
                              ExcMessage(where +
                                         " runs in the same "
                                         "direction in triangles " +
                                         std::to_string(p.cell) + " and " +
                                         std::to_string(q.cell) +
                                         "; one of them is clockwise."));
                  edges.push_back({{{v, p.other_vertex}},
                                   {{p.forward ? p.cell : q.cell,
                                     p.forward ? q.cell : p.cell}}});
                }
              first = last;
            }
        }
      return edges;
    }



    std::vector<SymmetricTensor<2, 2>>
    nodal_stresses(const std::vector<std::array<unsigned int, 3>> &triangles,
                   const std::vector<SymmetricTensor<2, 2>> &cell_stresses,
                   const std::vector<double>                &cell_areas,
                   const unsigned int                        n_vertices)
    {
      AssertDimension(cell_stresses.size(), triangles.size());
      AssertDimension(cell_areas.size(), triangles.size());
      std::vector<SymmetricTensor<2, 2>> stress(n_vertices);
      std::vector<double>                area(n_vertices, 0.);
      for (unsigned int c = 0; c < triangles.size(); ++c)
        {
          Assert(cell_areas[c] > 0.,
                 ExcMessage("nodal_stresses: cell " + std::to_string(c) +
                            " has a non-positive area."));
          for (const unsigned int v : triangles[c])
            {
              AssertIndexRange(v, n_vertices);
              stress[v] += cell_areas[c] * cell_stresses[c];
              area[v] += cell_areas[c];
            }
        }
      for (unsigned int v = 0; v < n_vertices; ++v)
        if (area[v] > 0.)
          stress[v] /= area[v];
      return stress;
    }



    namespace
    {
      /**
       * Mean of two entries of @p values for each edge, the entries picked
       * by @p index (the edge's cells or its vertices).
       */
      template <typename Index>
      std::vector<SymmetricTensor<2, 2>>
      edge_means(const std::vector<InteriorEdge>          &edges,
                 const std::vector<SymmetricTensor<2, 2>> &values,
                 const Index                              &index)
      {
        std::vector<SymmetricTensor<2, 2>> result(edges.size());
        for (unsigned int e = 0; e < edges.size(); ++e)
          {
            const std::array<unsigned int, 2> &i = index(edges[e]);
            AssertIndexRange(i[0], values.size());
            AssertIndexRange(i[1], values.size());
            result[e] = 0.5 * (values[i[0]] + values[i[1]]);
          }
        return result;
      }
    } // namespace



    std::vector<SymmetricTensor<2, 2>>
    cell_average_edge_stresses(
      const std::vector<InteriorEdge>          &edges,
      const std::vector<SymmetricTensor<2, 2>> &cell_stresses)
    {
      return edge_means(edges, cell_stresses, [](const InteriorEdge &edge) {
        return edge.cells;
      });
    }



    std::vector<SymmetricTensor<2, 2>>
    nodal_average_edge_stresses(
      const std::vector<InteriorEdge>          &edges,
      const std::vector<SymmetricTensor<2, 2>> &nodal_stresses)
    {
      return edge_means(edges, nodal_stresses, [](const InteriorEdge &edge) {
        return edge.vertices;
      });
    }



    std::vector<EdgeState>
    edge_states(const std::vector<InteriorEdge>                &edges,
                const std::vector<Point<2>>                    &vertices,
                const std::vector<std::array<unsigned int, 3>> &triangles,
                const std::vector<SymmetricTensor<2, 2>>       &cell_stresses,
                const std::vector<double>                      &cell_areas,
                const EdgeStressMethod                          method)
    {
      AssertDimension(cell_stresses.size(), triangles.size());
      Assert(method != EdgeStressMethod::nonlocal_average,
             ExcMessage("edge_states: the nonlocal average needs its "
                        "weights (NonlocalAverage)."));
      return edge_states(
        edges,
        vertices,
        method == EdgeStressMethod::cell_average ?
          cell_average_edge_stresses(edges, cell_stresses) :
          nodal_average_edge_stresses(edges,
                                      nodal_stresses(triangles,
                                                     cell_stresses,
                                                     cell_areas,
                                                     vertices.size())));
    }



    std::vector<EdgeState>
    edge_states(const std::vector<InteriorEdge>          &edges,
                const std::vector<Point<2>>              &vertices,
                const std::vector<SymmetricTensor<2, 2>> &stresses)
    {
      AssertDimension(stresses.size(), edges.size());
      std::vector<EdgeState> states(edges.size());
      for (unsigned int e = 0; e < edges.size(); ++e)
        states[e] = edge_state(stresses[e],
                               vertices[edges[e].vertices[0]],
                               vertices[edges[e].vertices[1]]);
      return states;
    }
  } // namespace fracture
} // namespace ndda
