// SPDX-License-Identifier: GPL-3.0-or-later
//
// Node splitting along marked edges of a plain triangle mesh (DESIGN.md,
// decision 6): the triangles around a vertex are grouped into fans that are
// connected through edges that are not split; every fan gets its own copy
// of the vertex. No CGAL in here: the fracture layer uses the same function
// on meshes that never went through the mesher.

#include <deal.II/base/exceptions.h>
#include <deal.II/base/types.h>

#include <ndda/geometry/block_mesh.h>

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace ndda
{
  namespace geometry
  {
    namespace
    {
      /**
       * Key of an undirected edge: the smaller vertex index in the high
       * bits, so that sorting the keys sorts the edges lexicographically.
       */
      std::uint64_t
      edge_key(const unsigned int a, const unsigned int b)
      {
        const std::uint64_t lo = std::min(a, b);
        const std::uint64_t hi = std::max(a, b);
        return (lo << 32) | hi;
      }


      std::string
      edge_to_string(const unsigned int a, const unsigned int b)
      {
        std::ostringstream s;
        s << "(" << a << ", " << b << ")";
        return s.str();
      }


      /**
       * Union-find with path halving and union by index: the root of a set
       * is always its smallest member, which keeps the numbering of the new
       * vertices independent of the order of the unions.
       */
      class DisjointSets
      {
      public:
        explicit DisjointSets(const std::size_t n)
          : parent(n)
        {
          std::iota(parent.begin(), parent.end(), 0u);
        }

        unsigned int
        find(unsigned int i)
        {
          while (parent[i] != i)
            {
              parent[i] = parent[parent[i]];
              i         = parent[i];
            }
          return i;
        }

        void
        join(const unsigned int i, const unsigned int j)
        {
          const unsigned int ri = find(i);
          const unsigned int rj = find(j);
          if (ri < rj)
            parent[rj] = ri;
          else if (rj < ri)
            parent[ri] = rj;
        }

      private:
        std::vector<unsigned int> parent;
      };


      /**
       * All triangle sides, sorted by edge key. Side j of triangle c joins
       * its local vertices j and (j+1)%3 and has the id 3c+j; the corner of
       * local vertex j has the same id.
       */
      using Sides = std::vector<std::pair<std::uint64_t, unsigned int>>;


      /**
       * Check that every triangle refers to vertices of the mesh.
       */
      void
      check_triangles(const BlockMesh &mesh)
      {
        const unsigned int n_vertices = mesh.vertices.size();
        const unsigned int n_cells    = mesh.triangles.size();
        for (unsigned int c = 0; c < n_cells; ++c)
          for (const unsigned int v : mesh.triangles[c])
            AssertThrow(v < n_vertices,
                        dealii::ExcMessage(
                          "split_vertices_along_edges: triangle " +
                          std::to_string(c) + " refers to vertex " +
                          std::to_string(v) + ", but the mesh has only " +
                          std::to_string(n_vertices) + " vertices."));
      }


      Sides
      sorted_sides(const BlockMesh &mesh)
      {
        const unsigned int n_cells = mesh.triangles.size();
        Sides              sides;
        sides.reserve(3 * std::size_t(n_cells));
        for (unsigned int c = 0; c < n_cells; ++c)
          for (unsigned int j = 0; j < 3; ++j)
            sides.emplace_back(edge_key(mesh.triangles[c][j],
                                        mesh.triangles[c][(j + 1) % 3]),
                               3 * c + j);
        std::sort(sides.begin(), sides.end());
        return sides;
      }


      /**
       * Whether the edge with the given key is a side of a triangle.
       */
      bool
      is_side(const Sides &sides, const std::uint64_t key)
      {
        const auto it =
          std::lower_bound(sides.begin(), sides.end(), std::make_pair(key, 0u));
        return it != sides.end() && it->first == key;
      }


      void
      sort_unique(std::vector<std::uint64_t> &keys)
      {
        std::sort(keys.begin(), keys.end());
        keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
      }


      /**
       * The keys of the edges to split, sorted and unique, after checking
       * that every edge is a side of the mesh; marks the vertices on them
       * in @p on_split_edge.
       */
      std::vector<std::uint64_t>
      split_edge_keys(const BlockMesh                                &mesh,
                      const Sides                                    &sides,
                      const std::vector<std::array<unsigned int, 2>> &edges,
                      std::vector<bool> &on_split_edge)
      {
        const unsigned int         n_vertices = mesh.vertices.size();
        std::vector<std::uint64_t> split_keys;
        split_keys.reserve(edges.size());
        for (const auto &e : edges)
          {
            AssertThrow(e[0] != e[1] && e[0] < n_vertices && e[1] < n_vertices,
                        dealii::ExcMessage(
                          "split_vertices_along_edges: the edge " +
                          edge_to_string(e[0], e[1]) +
                          " is not a pair of two different vertices of the "
                          "mesh."));
            const std::uint64_t key = edge_key(e[0], e[1]);
            AssertThrow(is_side(sides, key),
                        dealii::ExcMessage(
                          "split_vertices_along_edges: the edge " +
                          edge_to_string(e[0], e[1]) +
                          " is not a side of any triangle of the mesh."));
            split_keys.push_back(key);
            on_split_edge[e[0]] = true;
            on_split_edge[e[1]] = true;
          }
        sort_unique(split_keys);
        return split_keys;
      }


      /**
       * The keys of the edges to split and of the edges that are crack faces
       * already (from an earlier split): both end up in crack_edges. Sorted
       * and unique.
       */
      std::vector<std::uint64_t>
      crack_edge_keys(const BlockMesh                  &mesh,
                      const Sides                      &sides,
                      const std::vector<std::uint64_t> &split_keys)
      {
        std::vector<std::uint64_t> crack_keys = split_keys;
        for (const auto &e : mesh.crack_edges)
          {
            const std::uint64_t key = edge_key(e[0], e[1]);
            AssertThrow(is_side(sides, key),
                        dealii::ExcMessage(
                          "split_vertices_along_edges: the crack edge " +
                          edge_to_string(e[0], e[1]) +
                          " stored in the mesh is not a side of any "
                          "triangle."));
            crack_keys.push_back(key);
          }
        sort_unique(crack_keys);
        return crack_keys;
      }


      /**
       * The corner (id 3c+j) of the triangle of @p side at @p vertex.
       */
      unsigned int
      corner_of(const BlockMesh   &mesh,
                const unsigned int side,
                const unsigned int vertex)
      {
        const unsigned int c = side / 3;
        for (unsigned int j = 0; j < 3; ++j)
          if (mesh.triangles[c][j] == vertex)
            return 3 * c + j;
        Assert(false, dealii::ExcInternalError());
        return 3 * c;
      }


      /**
       * Connect the corners of two triangles that share an edge that is not
       * split: the corners at the same vertex then belong to the same fan.
       * Only the corners at vertices on split edges matter.
       */
      DisjointSets
      join_fans(const BlockMesh                  &mesh,
                const Sides                      &sides,
                const std::vector<std::uint64_t> &split_keys,
                const std::vector<bool>          &on_split_edge)
      {
        DisjointSets fans(3 * std::size_t(mesh.triangles.size()));
        for (std::size_t i = 0; i < sides.size();)
          {
            std::size_t end = i + 1;
            while (end < sides.size() && sides[end].first == sides[i].first)
              ++end;
            const unsigned int a = sides[i].first >> 32;
            const unsigned int b = sides[i].first & 0xffffffffu;
            AssertThrow(end - i <= 2,
                        dealii::ExcMessage(
                          "split_vertices_along_edges: the edge " +
                          edge_to_string(a, b) + " is shared by " +
                          std::to_string(end - i) +
                          " triangles; a valid mesh has at most two."));
            if (end - i == 2 && !std::binary_search(split_keys.begin(),
                                                    split_keys.end(),
                                                    sides[i].first))
              for (const unsigned int v : {a, b})
                if (on_split_edge[v])
                  fans.join(corner_of(mesh, sides[i].second, v),
                            corner_of(mesh, sides[i + 1].second, v));
            i = end;
          }
        return fans;
      }


      /**
       * Give every fan its vertex and renumber the triangles. Of the fans
       * at a vertex, the one with the first cell in an order of the plane
       * (its centroid's x, then y) keeps the original vertex, the others
       * get new vertices in that order, vertex by vertex. What the original
       * number carries (a contact's memory, a constraint) so stays with the
       * same side of the crack, whatever the order of the cells: with the
       * fan of the lowest cell index instead, the side would follow the
       * mesh's numbering. Returns the origin of every vertex.
       */
      std::vector<unsigned int>
      number_fans(BlockMesh               &mesh,
                  DisjointSets            &fans,
                  const std::vector<bool> &on_split_edge)
      {
        const unsigned int        n_vertices = mesh.vertices.size();
        const unsigned int        n_cells    = mesh.triangles.size();
        std::vector<unsigned int> origin(n_vertices);
        std::iota(origin.begin(), origin.end(), 0u);
        const auto centroid = [&](const unsigned int c) {
          const auto &t = mesh.triangles[c];
          return Point<2>(
            (mesh.vertices[t[0]] + mesh.vertices[t[1]] + mesh.vertices[t[2]]) /
            3.);
        };
        const auto before = [](const Point<2> &a, const Point<2> &b) {
          return a[0] < b[0] || (a[0] == b[0] && a[1] < b[1]);
        };
        // Every fan's first cell in the plane's order, and the fans at
        // every split vertex.
        std::vector<Point<2>> fan_first(3 * std::size_t(n_cells));
        std::vector<bool>     fan_seen(3 * std::size_t(n_cells), false);
        std::vector<std::vector<unsigned int>> fans_at(n_vertices);
        for (unsigned int corner = 0; corner < 3 * n_cells; ++corner)
          {
            const unsigned int v = mesh.triangles[corner / 3][corner % 3];
            if (!on_split_edge[v])
              continue;
            const unsigned int root = fans.find(corner);
            const Point<2>     p    = centroid(corner / 3);
            if (!fan_seen[root])
              {
                fan_seen[root]  = true;
                fan_first[root] = p;
                fans_at[v].push_back(root);
              }
            else if (before(p, fan_first[root]))
              fan_first[root] = p;
          }
        std::vector<unsigned int> fan_vertex(
          3 * std::size_t(n_cells), dealii::numbers::invalid_unsigned_int);
        for (unsigned int v = 0; v < n_vertices; ++v)
          {
            auto &at = fans_at[v];
            std::sort(at.begin(),
                      at.end(),
                      [&](const unsigned int a, const unsigned int b) {
                        return before(fan_first[a], fan_first[b]) ||
                               (!before(fan_first[b], fan_first[a]) && a < b);
                      });
            for (unsigned int i = 0; i < at.size(); ++i)
              if (i == 0)
                fan_vertex[at[i]] = v;
              else
                {
                  fan_vertex[at[i]] = origin.size();
                  origin.push_back(v);
                  mesh.vertices.push_back(mesh.vertices[v]);
                }
          }
        for (unsigned int corner = 0; corner < 3 * n_cells; ++corner)
          {
            auto &v = mesh.triangles[corner / 3][corner % 3];
            if (on_split_edge[v])
              v = fan_vertex[fans.find(corner)];
          }
        return origin;
      }


      /**
       * Every side of a triangle whose edge was split or was a crack face
       * before is a crack face now. Sides keep the orientation of their
       * triangle, so the body lies to the left of every crack edge.
       */
      void
      collect_crack_edges(BlockMesh                        &mesh,
                          const Sides                      &sides,
                          const std::vector<std::uint64_t> &crack_keys)
      {
        mesh.crack_edges.clear();
        for (const auto &side : sides)
          if (std::binary_search(crack_keys.begin(),
                                 crack_keys.end(),
                                 side.first))
            {
              const unsigned int c = side.second / 3;
              const unsigned int j = side.second % 3;
              mesh.crack_edges.push_back(
                {{mesh.triangles[c][j], mesh.triangles[c][(j + 1) % 3]}});
            }
      }
    } // namespace



    std::vector<unsigned int>
    split_vertices_along_edges(
      BlockMesh                                      &mesh,
      const std::vector<std::array<unsigned int, 2>> &edges)
    {
      check_triangles(mesh);
      const Sides       sides = sorted_sides(mesh);
      std::vector<bool> on_split_edge(mesh.vertices.size(), false);
      const std::vector<std::uint64_t> split_keys =
        split_edge_keys(mesh, sides, edges, on_split_edge);
      const std::vector<std::uint64_t> crack_keys =
        crack_edge_keys(mesh, sides, split_keys);

      DisjointSets fans = join_fans(mesh, sides, split_keys, on_split_edge);
      const std::vector<unsigned int> origin =
        number_fans(mesh, fans, on_split_edge);
      collect_crack_edges(mesh, sides, crack_keys);
      return origin;
    }
  } // namespace geometry
} // namespace ndda
