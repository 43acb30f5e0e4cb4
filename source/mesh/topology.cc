// SPDX-License-Identifier: GPL-3.0-or-later

#include <deal.II/base/exceptions.h>
#include <deal.II/base/types.h>

#include <ndda/mesh/topology.h>

#include <string>

namespace ndda
{
  namespace topology
  {
    using dealii::numbers::invalid_unsigned_int;


    HalfEdges::HalfEdges(
      const std::vector<std::array<unsigned int, 3>> &triangles,
      const unsigned int                              n_vertices)
      : triangles(triangles)
      , offsets(n_vertices + 1, 0)
      , sides(3 * triangles.size())
      , twins(3 * triangles.size(), invalid_unsigned_int)
    {
      // Counting sort of the sides by their first vertex.
      for (unsigned int c = 0; c < triangles.size(); ++c)
        for (const unsigned int v : triangles[c])
          {
            AssertThrow(v < n_vertices,
                        dealii::ExcMessage(
                          "Mesh: triangle " + std::to_string(c) +
                          " refers to vertex " + std::to_string(v) +
                          ", but the mesh has only " +
                          std::to_string(n_vertices) + " vertices."));
            ++offsets[v + 1];
          }
      for (unsigned int v = 0; v < n_vertices; ++v)
        offsets[v + 1] += offsets[v];
      std::vector<unsigned int> fill(offsets.begin(), offsets.end() - 1);
      for (unsigned int s = 0; s < sides.size(); ++s)
        sides[fill[from(s)]++] = s;

      for (unsigned int s = 0; s < sides.size(); ++s)
        {
          AssertThrow(find(from(s), to(s)) == s,
                      dealii::ExcMessage(
                        "Mesh: two triangles run through the edge from "
                        "vertex " +
                        std::to_string(from(s)) + " to vertex " +
                        std::to_string(to(s)) +
                        " in the same direction (triangles " +
                        std::to_string(find(from(s), to(s)) / 3) + " and " +
                        std::to_string(s / 3) +
                        "): one of them is clockwise, or more than two "
                        "triangles share the edge."));
          twins[s] = find(to(s), from(s));
        }
    }



    unsigned int
    HalfEdges::find(const unsigned int a, const unsigned int b) const
    {
      for (unsigned int i = offsets[a]; i < offsets[a + 1]; ++i)
        if (to(sides[i]) == b)
          return sides[i];
      return invalid_unsigned_int;
    }



    std::vector<unsigned int>
    connected_components(const HalfEdges   &half_edges,
                         const unsigned int n_triangles,
                         unsigned int      &n_components)
    {
      std::vector<unsigned int> component(n_triangles, invalid_unsigned_int);
      std::vector<unsigned int> stack;
      n_components = 0;
      for (unsigned int start = 0; start < n_triangles; ++start)
        {
          if (component[start] != invalid_unsigned_int)
            continue;
          component[start] = n_components;
          stack.push_back(start);
          while (!stack.empty())
            {
              const unsigned int c = stack.back();
              stack.pop_back();
              for (unsigned int j = 0; j < 3; ++j)
                {
                  const unsigned int twin = half_edges.twin(3 * c + j);
                  if (twin != invalid_unsigned_int &&
                      component[twin / 3] == invalid_unsigned_int)
                    {
                      component[twin / 3] = n_components;
                      stack.push_back(twin / 3);
                    }
                }
            }
          ++n_components;
        }
      return component;
    }



    std::vector<BoundaryLoop>
    boundary_loops(const geometry::BlockMesh       &mesh,
                   const std::vector<BoundaryEdge> &edges)
    {
      const HalfEdges half_edges(mesh.triangles, mesh.vertices.size());

      // The boundary edge of every side that lies on the boundary.
      std::vector<unsigned int> edge_of_side(3 * mesh.triangles.size(),
                                             invalid_unsigned_int);
      for (unsigned int e = 0; e < edges.size(); ++e)
        {
          const unsigned int side = 3 * edges[e].cell + edges[e].local_vertex;
          AssertThrow(edges[e].cell < mesh.triangles.size() &&
                        half_edges.from(side) == edges[e].v0 &&
                        half_edges.to(side) == edges[e].v1 &&
                        half_edges.twin(side) == invalid_unsigned_int,
                      dealii::ExcMessage(
                        "boundary_loops: edge " + std::to_string(e) +
                        " is not a boundary edge of the mesh; pass the "
                        "edges of boundary_edges(mesh)."));
          edge_of_side[side] = e;
        }

      std::vector<BoundaryLoop> loops;
      std::vector<bool>         visited(edges.size(), false);
      for (unsigned int first = 0; first < edges.size(); ++first)
        {
          if (visited[first])
            continue;
          BoundaryLoop loop;
          loop.block       = edges[first].block;
          loop.signed_area = 0.;
          for (unsigned int e = first; !visited[e];)
            {
              visited[e] = true;
              loop.edges.push_back(e);
              const auto &a = mesh.vertices[edges[e].v0];
              const auto &b = mesh.vertices[edges[e].v1];
              loop.signed_area += 0.5 * (a[0] * b[1] - b[0] * a[1]);
              AssertThrow(edges[e].block == loop.block,
                          dealii::ExcMessage(
                            "boundary_loops: a boundary loop runs through "
                            "blocks " +
                            std::to_string(loop.block) + " and " +
                            std::to_string(edges[e].block) +
                            "; blocks must not share vertices."));

              // Turn around the end vertex, through the triangles of the
              // fan, to the next side that lies on the boundary.
              unsigned int side =
                HalfEdges::next(3 * edges[e].cell + edges[e].local_vertex);
              while (half_edges.twin(side) != invalid_unsigned_int)
                side = HalfEdges::next(half_edges.twin(side));
              e = edge_of_side[side];
              AssertThrow(e != invalid_unsigned_int,
                          dealii::ExcMessage(
                            "boundary_loops: the boundary edge from vertex " +
                            std::to_string(half_edges.from(side)) +
                            " to vertex " +
                            std::to_string(half_edges.to(side)) +
                            " is missing from the list of boundary edges."));
            }
          AssertThrow(loop.edges.front() == first &&
                        edges[loop.edges.back()].v1 == edges[first].v0,
                      dealii::ExcInternalError());
          loops.push_back(std::move(loop));
        }
      return loops;
    }
  } // namespace topology
} // namespace ndda
