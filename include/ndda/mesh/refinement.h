// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_mesh_refinement_h
#define ndda_mesh_refinement_h

#include <deal.II/base/point.h>

#include <ndda/geometry/block_mesh.h>

#include <array>
#include <functional>
#include <vector>

namespace ndda
{
  /**
   * Local refinement of a block mesh by longest-edge bisection (Rivara's
   * LEPP algorithm): a triangle is split at the midpoint of its longest
   * edge, and so is the neighbour across that edge, after the neighbour's
   * own longest edge has been split if that is another one. The mesh stays
   * conforming (no hanging nodes), every new triangle is similar to one of
   * finitely many shapes, and the smallest angle is at least half the
   * smallest angle before (Rivara 1984). Area and outline are kept
   * exactly: new vertices lie on straight edges. doc/fracture.md,
   * "Refinement ahead of a running crack", has the rules and why.
   *
   * @ingroup mesh
   */
  namespace refinement
  {
    using dealii::Point;

    /**
     * Where the cells of a refined mesh come from. A bisected cell keeps
     * its index for one half; the other half is appended, so the cells of
     * the mesh before keep their indices (as parts of themselves), and
     * per-cell state carries over by origin.
     */
    struct RefineResult
    {
      /// For every cell of the new mesh, the cell of the old mesh it lies
      /// in.
      std::vector<unsigned int> cell_origin;
      /// For every cell of the new mesh, its three vertices as points of
      /// the reference triangle of its origin cell (vertex 0 of the old
      /// cell at (0, 0), vertex 1 at (1, 0), vertex 2 at (0, 1)). The
      /// cells map linearly, so this locates every point of the new cell in
      /// the old one, in both the present and the initial geometry.
      std::vector<std::array<Point<2>, 3>> reference_vertices;
      /// Whether each cell of the new mesh is a part of its origin (it was
      /// bisected), rather than the old cell unchanged.
      std::vector<bool> is_part;
      /// The number of cells and vertices before.
      unsigned int n_old_cells = 0, n_old_vertices = 0;
      /// Bisections done (each adds one cell).
      unsigned int n_bisections = 0;
    };

    /**
     * Bisect the cells of @p mesh until the longest edge of every cell is
     * at most @p size_bound(block, centroid), the centroid in the present
     * geometry, edge lengths in the initial one (where both faces of a
     * crack have the same length; a block's strains are small). New
     * vertices are the midpoints of edges, in the present geometry
     * (mesh.vertices) and the initial one (@p initial_vertices, which is
     * extended alongside); they are appended. Triangles stay
     * counter-clockwise; cells of the mesh keep their block and material.
     *
     * Crack faces (mesh.crack_edges) are bisected like other edges and
     * their entries become two. The two faces of an open crack (one cell
     * each, ends with the same initial positions) are bisected together,
     * the second in its cell whether or not it is that cell's longest
     * side: they stay copies of one edge, as crack() made them. A closed
     * crack (two cells on its edge) is an interior edge to the algorithm.
     *
     * @param max_cells An ExcMessage is thrown (and the mesh is left
     *   half refined: call this on a copy) if the mesh would get more cells.
     */
    RefineResult
    bisect_to_size(
      geometry::BlockMesh   &mesh,
      std::vector<Point<2>> &initial_vertices,
      const std::function<double(unsigned int, const Point<2> &)> &size_bound,
      const unsigned int                                           max_cells);
  } // namespace refinement
} // namespace ndda

#endif
