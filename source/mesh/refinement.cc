// SPDX-License-Identifier: GPL-3.0-or-later
#include <deal.II/base/exceptions.h>

#include <ndda/mesh/refinement.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <map>
#include <string>
#include <unordered_map>
#include <utility>

namespace ndda
{
  namespace refinement
  {
    namespace
    {
      constexpr unsigned int none = std::numeric_limits<unsigned int>::max();

      std::uint64_t
      edge_key(const unsigned int a, const unsigned int b)
      {
        return a < b ? (std::uint64_t(a) << 32) | b :
                       (std::uint64_t(b) << 32) | a;
      }



      /**
       * The mesh being bisected: its triangles, the cells on each edge and
       * the midpoints made so far.
       */
      class Bisector
      {
      public:
        Bisector(geometry::BlockMesh   &mesh,
                 std::vector<Point<2>> &initial,
                 RefineResult          &result)
          : mesh(mesh)
          , initial(initial)
          , result(result)
        {
          edge_cells.reserve(2 * mesh.triangles.size());
          for (unsigned int c = 0; c < mesh.triangles.size(); ++c)
            for (unsigned int i = 0; i < 3; ++i)
              add(side_key(c, i), c);
          // The two faces of an open crack are copies of one edge: their
          // ends have the same initial positions.
          std::map<std::array<double, 4>, std::vector<std::uint64_t>> copies;
          for (unsigned int i = 0; i < mesh.crack_edges.size(); ++i)
            {
              const auto &e   = mesh.crack_edges[i];
              const auto  key = edge_key(e[0], e[1]);
              face_entries[key].push_back(i);
              const auto cells = edge_cells.find(key);
              if (cells == edge_cells.end() || cells->second[1] != none)
                continue;
              const auto &p      = initial[e[0]];
              const auto &q      = initial[e[1]];
              const bool p_first = p[0] < q[0] || (p[0] == q[0] && p[1] < q[1]);
              const auto &lo     = p_first ? p : q;
              const auto &hi     = p_first ? q : p;
              auto       &faces  = copies[{{lo[0], lo[1], hi[0], hi[1]}}];
              if (std::find(faces.begin(), faces.end(), key) == faces.end())
                faces.push_back(key);
            }
          for (const auto &[position, faces] : copies)
            if (faces.size() == 2)
              {
                twin[faces[0]] = faces[1];
                twin[faces[1]] = faces[0];
              }
        }

        /**
         * One step of the LEPP algorithm from cell @p t: follow the
         * neighbours across longest edges to the terminal edge and bisect
         * it (in one cell on the boundary, in both otherwise). A face of
         * an open crack is bisected with its copy on the crack's other side
         * (the other face's cell is split there, whether or not it is that
         * cell's longest side), so that the faces stay copies of each other
         * and the crack's node pairs are kept.
         */
        void
        lepp_step(const unsigned int t)
        {
          unsigned int cell = t;
          // The path's edges grow strictly (in the order of longest_side()),
          // so it ends; the bound only guards against a corrupt mesh.
          for (unsigned int n = 0; n <= mesh.triangles.size(); ++n)
            {
              const unsigned int  side  = longest_side(cell);
              const std::uint64_t key   = side_key(cell, side);
              const auto         &cells = edge_cells.at(key);
              const unsigned int other = cells[0] == cell ? cells[1] : cells[0];
              if (other == none)
                {
                  bisect_face(cell, side);
                  return;
                }
              const unsigned int other_side = longest_side(other);
              if (side_key(other, other_side) == key)
                {
                  const unsigned int m = bisect(cell, side);
                  bisect(other, other_side, m);
                  return;
                }
              cell = other;
            }
          AssertThrow(false,
                      dealii::ExcInternalError("refinement: a longest-edge "
                                               "path does not end."));
        }

        /**
         * The longest side of cell @p c in the initial geometry, ties broken
         * by the edge key. Both faces of an open crack have the same length
         * there and the same key in this order (the smaller of the two), so
         * that a longest-edge path never returns to a face whose copy it
         * left (bisect_face()).
         */
        unsigned int
        longest_side(const unsigned int c) const
        {
          unsigned int  best     = 0;
          double        best_len = -1;
          std::uint64_t best_key = 0;
          for (unsigned int i = 0; i < 3; ++i)
            {
              const double len  = length_squared(c, i);
              auto         key  = side_key(c, i);
              const auto   copy = twin.find(key);
              if (copy != twin.end())
                key = std::min(key, copy->second);
              if (len > best_len || (len == best_len && key < best_key))
                {
                  best     = i;
                  best_len = len;
                  best_key = key;
                }
            }
          return best;
        }

        /** The squared length of side @p i of cell @p c, initial geometry. */
        double
        length_squared(const unsigned int c, const unsigned int i) const
        {
          const auto &t = mesh.triangles[c];
          return initial[t[i]].distance_square(initial[t[(i + 1) % 3]]);
        }

      private:
        /**
         * Bisect side @p side of cell @p c, which only c has, and its copy
         * across the crack if it is a crack face. If the copy is not the
         * longest side of its cell, that cell is refined first (one LEPP
         * step; the caller comes back) until the part of it at the face
         * has the face as its longest side.
         */
        void
        bisect_face(const unsigned int c, const unsigned int side)
        {
          const std::uint64_t key  = side_key(c, side);
          const auto          copy = twin.find(key);
          if (copy == twin.end())
            {
              bisect(c, side);
              return;
            }
          const std::uint64_t key2  = copy->second;
          const unsigned int  c2    = edge_cells.at(key2)[0];
          unsigned int        side2 = 0;
          while (side_key(c2, side2) != key2)
            ++side2;
          if (longest_side(c2) != side2)
            {
              lepp_step(c2);
              return;
            }
          const auto         t  = mesh.triangles[c];
          const auto         t2 = mesh.triangles[c2];
          const unsigned int a = t[side], b = t[(side + 1) % 3];
          // The copy of a on the other face (the faces run the other way).
          const unsigned int a2 = t2[(side2 + 1) % 3], b2 = t2[side2];
          Assert(initial[a] == initial[a2] && initial[b] == initial[b2],
                 dealii::ExcInternalError());
          const unsigned int m  = bisect(c, side);
          const unsigned int m2 = bisect(c2, side2);
          twin.erase(key);
          twin.erase(key2);
          const auto link = [&](const std::uint64_t k, const std::uint64_t k2) {
            twin[k]  = k2;
            twin[k2] = k;
          };
          link(edge_key(a, m), edge_key(a2, m2));
          link(edge_key(m, b), edge_key(m2, b2));
        }

        std::uint64_t
        side_key(const unsigned int c, const unsigned int i) const
        {
          const auto &t = mesh.triangles[c];
          return edge_key(t[i], t[(i + 1) % 3]);
        }

        void
        add(const std::uint64_t key, const unsigned int c)
        {
          auto it = edge_cells.find(key);
          if (it == edge_cells.end())
            edge_cells.emplace(key, std::array<unsigned int, 2>{{c, none}});
          else
            {
              AssertThrow(it->second[1] == none,
                          dealii::ExcInternalError(
                            "refinement: an edge with three cells."));
              it->second[1] = c;
            }
        }

        void
        replace(const std::uint64_t key,
                const unsigned int  old_cell,
                const unsigned int  new_cell)
        {
          auto &cells = edge_cells.at(key);
          if (cells[0] == old_cell)
            cells[0] = new_cell;
          else
            {
              Assert(cells[1] == old_cell, dealii::ExcInternalError());
              cells[1] = new_cell;
            }
          if (cells[0] == none)
            std::swap(cells[0], cells[1]);
          if (cells[0] == none)
            edge_cells.erase(key);
        }

        /**
         * Split cell @p c at the midpoint of its side @p side (made now, or
         * the vertex @p m if the neighbour was split there already): c keeps
         * the half at the side's start, the other half is appended.
         * Returns the midpoint.
         */
        unsigned int
        bisect(const unsigned int c,
               const unsigned int side,
               unsigned int       m = none)
        {
          const auto         t = mesh.triangles[c];
          const unsigned int a = t[side], b = t[(side + 1) % 3],
                             o = t[(side + 2) % 3];
          if (m == none)
            {
              m = mesh.vertices.size();
              mesh.vertices.push_back(
                Point<2>(0.5 * (mesh.vertices[a] + mesh.vertices[b])));
              initial.push_back(Point<2>(0.5 * (initial[a] + initial[b])));
            }
          const auto         ref = result.reference_vertices[c];
          const auto        &ra  = ref[side];
          const auto        &rb  = ref[(side + 1) % 3];
          const auto        &ro  = ref[(side + 2) % 3];
          const Point<2>     rm  = Point<2>(0.5 * (ra + rb));
          const unsigned int n   = mesh.triangles.size();
          AssertThrow(n < max_cells,
                      dealii::ExcMessage(too_many_cells_message));

          mesh.triangles[c] = {{a, m, o}};
          mesh.triangles.push_back({{m, b, o}});
          mesh.cell_block.push_back(mesh.cell_block[c]);
          mesh.cell_material.push_back(mesh.cell_material[c]);
          result.cell_origin.push_back(result.cell_origin[c]);
          result.reference_vertices[c] = {{ra, rm, ro}};
          result.reference_vertices.push_back({{rm, rb, ro}});
          result.is_part[c] = true;
          result.is_part.push_back(true);
          changed.push_back(c);
          changed.push_back(n);
          ++result.n_bisections;

          // A crack face (open or closed) becomes two.
          const auto faces = face_entries.find(edge_key(a, b));
          if (faces != face_entries.end())
            {
              const std::vector<unsigned int> entries = faces->second;
              face_entries.erase(faces);
              for (const unsigned int i : entries)
                {
                  const auto e           = mesh.crack_edges[i];
                  mesh.crack_edges[i][1] = m;
                  face_entries[edge_key(e[0], m)].push_back(i);
                  face_entries[edge_key(m, e[1])].push_back(
                    mesh.crack_edges.size());
                  mesh.crack_edges.push_back({{m, e[1]}});
                }
            }
          replace(edge_key(a, b), c, none);
          add(edge_key(a, m), c);
          add(edge_key(m, b), n);
          add(edge_key(m, o), c);
          add(edge_key(m, o), n);
          replace(edge_key(b, o), c, n);
          return m;
        }

      public:
        unsigned int max_cells = none;
        std::string  too_many_cells_message;
        /// The cells bisect() has made or changed (with repeats).
        std::vector<unsigned int> changed;

      private:
        geometry::BlockMesh   &mesh;
        std::vector<Point<2>> &initial;
        RefineResult          &result;
        /// Where every crack face is in mesh.crack_edges.
        std::unordered_map<std::uint64_t, std::vector<unsigned int>>
          face_entries;
        /// The copy of every face of an open crack on its other side.
        std::unordered_map<std::uint64_t, std::uint64_t> twin;
        /// The one or two cells on every edge.
        std::unordered_map<std::uint64_t, std::array<unsigned int, 2>>
          edge_cells;
      };
    } // namespace



    RefineResult
    bisect_to_size(
      geometry::BlockMesh   &mesh,
      std::vector<Point<2>> &initial_vertices,
      const std::function<double(unsigned int, const Point<2> &)> &size_bound,
      const unsigned int                                           max_cells)
    {
      AssertThrow(initial_vertices.size() == mesh.vertices.size(),
                  dealii::ExcMessage("bisect_to_size: the initial and the "
                                     "present vertices differ in number."));
      RefineResult result;
      result.n_old_cells    = mesh.triangles.size();
      result.n_old_vertices = mesh.vertices.size();
      result.cell_origin.resize(result.n_old_cells);
      result.reference_vertices.assign(
        result.n_old_cells, {{Point<2>(0, 0), Point<2>(1, 0), Point<2>(0, 1)}});
      result.is_part.assign(result.n_old_cells, false);
      for (unsigned int c = 0; c < result.n_old_cells; ++c)
        result.cell_origin[c] = c;

      Bisector bisector(mesh, initial_vertices, result);
      bisector.max_cells = max_cells;
      bisector.too_many_cells_message =
        "the refined mesh would have more than " + std::to_string(max_cells) +
        " cells: raise the size (or the growth rate), or the limit.";

      // Passes over the cells: each cell too large is bisected once (with
      // the cells its longest-edge path needs), which halves it. A cell
      // that is small enough stays so until a bisection changes it, so
      // after the first pass over all cells, a pass looks only at the
      // cells the one before made or changed.
      std::vector<unsigned int> candidates(mesh.triangles.size());
      for (unsigned int c = 0; c < candidates.size(); ++c)
        candidates[c] = c;
      while (!candidates.empty())
        {
          std::vector<std::pair<unsigned int, std::array<unsigned int, 3>>>
            too_large;
          for (const unsigned int c : candidates)
            {
              const auto    &t = mesh.triangles[c];
              const Point<2> centroid((mesh.vertices[t[0]] +
                                       mesh.vertices[t[1]] +
                                       mesh.vertices[t[2]]) /
                                      3.);
              const double   bound = size_bound(mesh.cell_block[c], centroid);
              const double   longest =
                bisector.length_squared(c, bisector.longest_side(c));
              if (longest > bound * bound)
                too_large.emplace_back(c, t);
            }
          bisector.changed.clear();
          for (const auto &[c, shape] : too_large)
            // An earlier cell's path may have split c already: it is
            // smaller then, and the next pass looks at it again.
            while (mesh.triangles[c] == shape)
              bisector.lepp_step(c);
          candidates.swap(bisector.changed);
          std::sort(candidates.begin(), candidates.end());
          candidates.erase(std::unique(candidates.begin(), candidates.end()),
                           candidates.end());
        }
      return result;
    }
  } // namespace refinement
} // namespace ndda
