// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_mesh_boundary_edges_h
#define ndda_mesh_boundary_edges_h

#include <ndda/geometry/block_mesh.h>

#include <vector>

namespace ndda
{
  /**
   * A boundary edge of the mesh: an edge used by exactly one triangle,
   * oriented as in that triangle, so that going from v0 to v1 the body
   * lies on the left (counter-clockwise around the block's outer boundary,
   * clockwise around holes, and the two faces of a crack run in opposite
   * directions).
   *
   * @ingroup mesh
   */
  struct BoundaryEdge
  {
    /// First vertex (index into the mesh's vertices).
    unsigned int v0;
    /// Second vertex.
    unsigned int v1;
    /// Block of the triangle the edge belongs to.
    unsigned int block;
    /// The triangle (its index in the mesh, which is the active cell
    /// index of the Triangulation built from it).
    unsigned int cell = static_cast<unsigned int>(-1);
    /// Local index of v0 in that triangle; v1 is (local_vertex + 1) % 3.
    unsigned int local_vertex = 0;
  };

  /**
   * The boundary edges of @p mesh: every edge used by exactly one
   * triangle, oriented as in that triangle, with that triangle's block.
   * The order is deterministic: sorted by (v0, v1). Cost O(n log n) in
   * the number of triangles. Contact detection, the boundary loops of
   * fracture and the contact handler all index these edges.
   *
   * Throws dealii::ExcMessage if an edge is used by more than two
   * triangles.
   *
   * @ingroup mesh
   */
  std::vector<BoundaryEdge>
  boundary_edges(const geometry::BlockMesh &mesh);
} // namespace ndda

#endif
