// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_geometry_block_mesh_h
#define ndda_geometry_block_mesh_h

#include <deal.II/base/point.h>

#include <ndda/geometry/size_field.h>

#include <array>
#include <string>
#include <vector>

namespace ndda
{
  /**
   * Scene geometry as plain data: what the `.prm` file describes, before and
   * after meshing. Nothing in here depends on CGAL; the CGAL code lives in
   * source/geometry/ only (it is heavy to compile and GPL-3.0-or-later).
   *
   * @ingroup geometry
   */
  namespace geometry
  {
    using dealii::Point;

    /**
     * A straight segment, for example a joint or a pre-existing crack.
     */
    struct Segment
    {
      Point<2> a;
      Point<2> b;
    };

    /**
     * One block given as a polygon: an outer ring, holes, and pre-existing
     * crack segments that lie inside the block. Rings may be given
     * clockwise or counter-clockwise, with or without the first point
     * repeated at the end.
     */
    struct BlockDescription
    {
      /// Name of the block in the `.prm` file, used in error messages.
      std::string name;
      /// Outer ring.
      std::vector<Point<2>> outer;
      /// Hole rings; each lies strictly inside the outer ring.
      std::vector<std::vector<Point<2>>> holes;
      /// Crack segments inside the block. Their faces are split: the two
      /// sides of a crack get separate vertices, except at a crack tip that
      /// lies inside the block.
      std::vector<Segment> cracks;
      /// Material id of all cells of this block.
      unsigned int material_id = 0;
      /// Upper bound for the length of a triangle edge (m). Zero: use
      /// target_n_cells instead.
      double mesh_size = 0.;
      /// Approximate number of triangles wanted in this block. Used only if
      /// mesh_size is zero.
      unsigned int target_n_cells = 0;
    };

    /**
     * A rock region that is cut into blocks by joint segments (DDA's
     * "block cutting"). Every face of the arrangement of the region's
     * boundary and the joints that lies inside the region becomes a block.
     * Parts of joints that do not separate two faces (dangling ends) are
     * dropped if @p keep_dangling_as_cracks is false, and become
     * pre-existing cracks of the block they lie in otherwise.
     */
    struct RegionDescription
    {
      std::string                        name;
      std::vector<Point<2>>              outer;
      std::vector<std::vector<Point<2>>> holes;
      std::vector<Segment>               joints;
      bool                               keep_dangling_as_cracks = true;
      unsigned int                       material_id             = 0;
      double                             mesh_size               = 0.;
      unsigned int                       target_n_cells          = 0;
    };

    /**
     * Everything needed to mesh a scene.
     */
    struct SceneGeometry
    {
      std::vector<BlockDescription>  blocks;
      std::vector<RegionDescription> regions;
      /// Points that must become mesh vertices if they lie inside or on the
      /// boundary of a block (load points, fixed points, measure points,
      /// end points of loaded boundary segments). Points outside every
      /// block are ignored here; the caller reports them.
      std::vector<Point<2>> required_vertices;
      /// Minimum angle of the Delaunay refinement (degrees).
      double min_angle = 30.;
      /// Largest number of cells the scene may need: a scene whose
      /// smallest possible mesh has more is refused before meshing.
      double max_cells = 1e6;
      /// Snapping tolerance, relative to the scene's size (the diagonal of
      /// the bounding box of all blocks and regions): corners of different
      /// blocks or regions closer than it become one point, and an overlap
      /// thinner than it is taken as touching. Zero: exact geometry.
      double snap_tolerance = 1e-9;
      /// Where the meshes are finer than their blocks' mesh sizes.
      MeshGrading grading;
    };

    /**
     * A meshed scene as plain arrays. Blocks never share vertices.
     */
    struct BlockMesh
    {
      std::vector<Point<2>> vertices;
      /// Triangles as vertex indices, counter-clockwise.
      std::vector<std::array<unsigned int, 3>> triangles;
      /// Block index of every triangle, in [0, block_names.size()).
      std::vector<unsigned int> cell_block;
      /// Material id of every triangle.
      std::vector<unsigned int> cell_material;
      /// One name per block: the block's name, or "<region>.<k>" for the
      /// k-th block cut from a region.
      std::vector<std::string> block_names;
      /// Edges (pairs of vertex indices, after splitting) that are faces of
      /// pre-existing cracks or joints. Used later for the joint material.
      std::vector<std::array<unsigned int, 2>> crack_edges;
    };

    /**
     * Check every block and region polygon (at least three distinct points,
     * simple, holes inside the outer ring and disjoint), check that no two
     * blocks or regions overlap, cut regions into blocks, mesh every block
     * with CGAL's constrained Delaunay mesher, and split the vertices along
     * crack segments.
     *
     * Throws dealii::ExcMessage naming the block and the problem for every
     * invalid input.
     */
    BlockMesh
    mesh_scene(const SceneGeometry &geometry);

    /**
     * Split vertices along the given edges of a triangle mesh: for every
     * vertex on such an edge, the triangles around it are grouped into fans
     * that are connected through edges not in @p edges; each fan gets its own
     * copy of the vertex. This covers an interior crack (tips keep one
     * vertex), a crack touching the boundary, and crossing cracks.
     *
     * @param mesh Mesh whose vertices are split in place; new vertices are
     *   appended, triangles are renumbered, crack_edges is filled with the
     *   split edges (both sides).
     * @param edges Edges to split, as pairs of vertex indices of @p mesh.
     * @return For every vertex of the returned mesh, the index of the vertex
     *   of the input mesh it was copied from.
     */
    std::vector<unsigned int>
    split_vertices_along_edges(
      BlockMesh                                      &mesh,
      const std::vector<std::array<unsigned int, 2>> &edges);
  } // namespace geometry
} // namespace ndda

#endif
