// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_mesh_topology_h
#define ndda_mesh_topology_h

#include <ndda/geometry/block_mesh.h>
#include <ndda/mesh/boundary_edges.h>

#include <array>
#include <vector>

namespace ndda
{
  /**
   * Topology of a triangle mesh given as plain arrays: which triangle side
   * runs along which edge, which triangles are connected, and the boundary
   * loops of each block. Node splitting (CrackableMesh::crack()) and the
   * contact layer use it. Everything here is linear in the number of
   * triangles and vertices; nothing depends on a Triangulation.
   *
   * @ingroup mesh
   */
  namespace topology
  {
    /**
     * The directed sides of the triangles of a mesh, grouped by their first
     * vertex (compressed rows, built by counting in O(n)). Side j of
     * triangle c runs from its local vertex j to local vertex (j+1)%3 and
     * has the id 3c+j. In a mesh of counter-clockwise triangles the triangle
     * lies on the left of each of its sides; the two triangles beside an
     * interior edge run through it in opposite directions, so the side of
     * the other triangle is the twin of a side.
     *
     * The object keeps a reference to the triangles; they must outlive it
     * and must not change while it is used.
     */
    class HalfEdges
    {
    public:
      /**
       * Index the sides of @p triangles.
       *
       * Throws dealii::ExcMessage if a vertex index is not below
       * @p n_vertices, or if two triangles run through the same edge in the
       * same direction (one of them is clockwise, or more than two
       * triangles share the edge).
       */
      HalfEdges(const std::vector<std::array<unsigned int, 3>> &triangles,
                const unsigned int                              n_vertices);

      /**
       * The id of the side that runs from @p a to @p b, or
       * dealii::numbers::invalid_unsigned_int if no triangle has it. Cost:
       * the number of triangles around @p a.
       */
      unsigned int
      find(const unsigned int a, const unsigned int b) const;

      /**
       * The id of the side of the neighbouring triangle along the same edge
       * (running the other way), or dealii::numbers::invalid_unsigned_int
       * if the side lies on the boundary.
       */
      unsigned int
      twin(const unsigned int side) const
      {
        return twins[side];
      }

      /** First vertex of a side. */
      unsigned int
      from(const unsigned int side) const
      {
        return triangles[side / 3][side % 3];
      }

      /** Second vertex of a side. */
      unsigned int
      to(const unsigned int side) const
      {
        return triangles[side / 3][(side + 1) % 3];
      }

      /**
       * The side that leaves the end vertex of @p side in the same
       * triangle.
       */
      static unsigned int
      next(const unsigned int side)
      {
        return 3 * (side / 3) + (side % 3 + 1) % 3;
      }

    private:
      const std::vector<std::array<unsigned int, 3>> &triangles;
      /// Sides leaving vertex v: sides[offsets[v]] to sides[offsets[v+1]].
      std::vector<unsigned int> offsets;
      std::vector<unsigned int> sides;
      std::vector<unsigned int> twins;
    };

    /**
     * The connected components of a mesh, two triangles being connected if
     * they share an edge (not only a vertex). Components are numbered in
     * the order of their lowest triangle index: the component of triangle 0
     * is 0, and so on.
     *
     * @param half_edges The sides of the mesh's triangles.
     * @param n_triangles Number of triangles.
     * @param n_components Set to the number of components.
     * @return The component of every triangle.
     */
    std::vector<unsigned int>
    connected_components(const HalfEdges   &half_edges,
                         const unsigned int n_triangles,
                         unsigned int      &n_components);

    /**
     * A closed loop of boundary edges: the thesis's "loop" (section 5.3)
     * as indices into the boundary edges of ndda::boundary_edges().
     * Every edge runs with its block on the left, so the end of edge i is
     * the start of edge i+1, and the end of the last edge is the start of
     * the first.
     */
    struct BoundaryLoop
    {
      /// Block of the triangles along the loop.
      unsigned int block;
      /// Indices into the boundary edges, in walking order.
      std::vector<unsigned int> edges;
      /// Area enclosed by the loop, by the shoelace formula over its
      /// edges: positive for the outer boundary of a block
      /// (counter-clockwise), negative around a hole (clockwise), zero for
      /// a crack whose two tips lie inside the block (a hole without
      /// volume). The loop areas of a block add up to the block's area.
      double signed_area;
    };

    /**
     * The boundary loops of @p mesh. From the end vertex of a boundary
     * edge, the walk turns through the triangles around that vertex,
     * crossing interior edges, until it reaches the next boundary edge; so
     * a vertex at which two loops touch (a vertex that two fans share
     * without sharing an edge) is passed correctly. Loops are ordered by
     * their lowest edge index and start with it. O(number of triangles).
     *
     * @param mesh The mesh.
     * @param edges Its boundary edges, from boundary_edges(mesh).
     */
    std::vector<BoundaryLoop>
    boundary_loops(const geometry::BlockMesh       &mesh,
                   const std::vector<BoundaryEdge> &edges);
  } // namespace topology
} // namespace ndda

#endif
