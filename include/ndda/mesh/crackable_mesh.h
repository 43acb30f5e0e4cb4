// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_mesh_crackable_mesh_h
#define ndda_mesh_crackable_mesh_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <deal.II/grid/tria.h>

#include <ndda/geometry/block_mesh.h>
#include <ndda/mesh/refinement.h>

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace ndda
{
  using namespace dealii;

  /**
   * An edge that crack() has cracked: the two triangles that shared it and
   * the two faces it has become.
   *
   * @ingroup mesh
   */
  struct CrackedEdge
  {
    /// The edge's vertices in the mesh before the crack, smaller index
    /// first.
    std::array<unsigned int, 2> old_vertices;
    /// The two triangles (active cell indices, the same before and after):
    /// cells[0] runs from old_vertices[0] to old_vertices[1] in its
    /// counter-clockwise order (it lies on the left of that direction),
    /// cells[1] on the right.
    std::array<unsigned int, 2> cells;
    /// The side of cells[i] on the crack, as vertices of the new mesh in
    /// that cell's counter-clockwise order: faces[0] runs from the copy of
    /// old_vertices[0] to the copy of old_vertices[1], faces[1] the other
    /// way. Each face runs with its cell on the left (BoundaryEdge's
    /// orientation). At a crack tip inside the block the two faces share the
    /// tip vertex; if both ends are such tips (thesis figure 5.4), the faces
    /// share both vertices and are not boundary edges yet (see
    /// CrackableMesh::crack()).
    std::array<std::array<unsigned int, 2>, 2> faces;
  };



  /**
   * What crack() did, as maps from the mesh before to the mesh after.
   * Cells are not renumbered: cell c of the new mesh is cell c of the old
   * one, with the same local vertex order and material id, so per-cell
   * state is carried over by identity.
   *
   * @ingroup mesh
   */
  struct CrackResult
  {
    /// For every vertex of the new mesh, the vertex of the old mesh it was
    /// copied from (new to old). Vertices of the old mesh keep their index
    /// (vertex_origin[v] == v for v below the old number of vertices);
    /// copies are appended. Use with state_transfer::transfer_vertex_data().
    std::vector<unsigned int> vertex_origin;
    /// The vertices the crack created, in increasing order (all indices at
    /// or above the old number of vertices).
    std::vector<unsigned int> new_vertices;
    /// Block of every cell of the new mesh.
    std::vector<unsigned int> cell_block;
    /// For every block of the new mesh, the block of the old mesh it comes
    /// from (new to old).
    std::vector<unsigned int> block_origin;
    /// For every block of the old mesh, the blocks of the new mesh it
    /// became (old to new): first the block itself (same index), then the
    /// blocks split off, in increasing order.
    std::vector<std::vector<unsigned int>> block_children;
    /// The cracked edges, one per distinct edge handed to crack(), ordered
    /// by their old vertices. Only the edges of this call: a closed crack
    /// of an earlier call that opens now (its tip split) is not listed;
    /// get_block_mesh().crack_edges and CrackableMesh::is_cracked() cover
    /// every crack face of the mesh.
    std::vector<CrackedEdge> cracked_edges;
    /// Set when crack() refined the cracked mesh (RefineAfterCrack) and
    /// bisected at least one cell: the cells of the cracked mesh (whose
    /// indices are those before the crack) to the refined one. The fields
    /// above describe the cracked mesh before this refinement.
    std::optional<refinement::RefineResult> refined;
  };



  /**
   * A refinement that CrackableMesh::crack() does on the cracked mesh
   * before it rebuilds the triangulation, so that a crack and the
   * refinement around its tips cost one rebuild (Fracture/Tip mesh size).
   *
   * @ingroup mesh
   */
  struct RefineAfterCrack
  {
    /// The bound on the longest edge of a cell of block b whose centroid
    /// is at x (CrackableMesh::refine()).
    using SizeBound = std::function<double(unsigned int, const Point<2> &)>;

    /// Given the cracked mesh and the initial positions of its vertices,
    /// the size bound. Empty: no refinement.
    std::function<SizeBound(const geometry::BlockMesh &,
                            const std::vector<Point<2>> &)>
      size_bound;
    /// Refuse (ExcMessage naming @p what, mesh unchanged, not cracked
    /// either) to make more cells than this.
    unsigned int max_cells = 0;
    /// What the refinement is for, to start its error messages.
    std::string what;
  };



  /**
   * The scene's triangulation and its block structure. Every block is its
   * own body: blocks never share vertices. The block of a cell is kept in a
   * vector indexed by the active cell index (deal.II keeps the cell order
   * of create_triangulation()), the material in the cell's material_id.
   *
   * After every build ndda checks the mesh itself (DESIGN.md decision 8),
   * because deal.II 9.4 accepts clockwise and degenerate triangles
   * silently.
   *
   * Fracture cracks interior edges with crack() (node splitting, thesis
   * section 5.3, DESIGN.md decision 6): the triangulation is rebuilt, cells
   * keep their index and vertex order, vertices are copied, and a block
   * that falls apart becomes several blocks. doc/fracture_mesh.md
   * describes the rules.
   *
   * @ingroup mesh
   */
  class CrackableMesh
  {
  public:
    /**
     * A mesh for a scene run on the processes of @p communicator: on one
     * process its triangulation is a plain Triangulation, on several a
     * parallel::shared::Triangulation whose cells each process owns a
     * range of (make_scene_triangulation()). Every process holds the
     * whole mesh and must build and crack it alike.
     */
    explicit CrackableMesh(const MPI_Comm communicator = MPI_COMM_SELF);

    /**
     * Build the triangulation from plain arrays (the output of the mesher
     * or of an import).
     */
    void
    build(const geometry::BlockMesh &mesh);

    /**
     * Build from a deal.II triangulation of triangles handed over by a
     * library user: one block per material id. Vertices shared by cells of
     * different material ids are split, so that blocks become separate
     * bodies. Cells of the same material id that are not connected through
     * shared edges become separate blocks too.
     */
    void
    build(const Triangulation<2> &triangulation);

    /**
     * Read a gmsh `.msh` file: every physical surface becomes a block (by
     * connected component), with material id @p material_of_tag(tag).
     */
    void
    read_msh(const std::string                               &filename,
             const std::function<unsigned int(unsigned int)> &material_of_tag);

    /** The triangulation. */
    const Triangulation<2> &
    get_triangulation() const
    {
      return *triangulation;
    }

    /** Block index of the active cell with the given index. */
    unsigned int
    block_of_cell(const unsigned int active_cell_index) const
    {
      return cell_block[active_cell_index];
    }

    unsigned int
    n_blocks() const
    {
      return block_names.size();
    }

    const std::vector<std::string> &
    get_block_names() const
    {
      return block_names;
    }

    /** The plain arrays the triangulation was built from. */
    const geometry::BlockMesh &
    get_block_mesh() const
    {
      return block_mesh;
    }

    /**
     * Crack the mesh along interior edges (node splitting, thesis section
     * 5.3; DESIGN.md decision 6), and rebuild the triangulation:
     *  1. Every edge must be an interior edge of a block, shared by two
     *     triangles, and not a crack already; otherwise an ExcMessage names
     *     the edge and nothing changes. An edge given twice counts once.
     *  2. Vertices are split by fans (geometry::split_vertices_along_edges):
     *     around every vertex of a cracked edge, the triangles connected
     *     through uncracked edges form a fan, and each fan gets its own copy
     *     of the vertex. A crack tip inside a block keeps one vertex (no new
     *     vertex), an end on a boundary or on an earlier crack gets one copy
     *     per side (one or two new vertices per edge, thesis figure 5.5).
     *     Cells keep their index, local vertex order and material id.
     *     An edge whose ends both stay single (both are tips inside the
     *     block, thesis figure 5.4) is only marked, as in the thesis: its
     *     faces share both vertices, so deal.II and contact still see one
     *     interior edge, and the crack cannot open until it grows. Later
     *     cracks treat it as cracked: growing through one of its tips
     *     splits that tip. is_cracked() tells such edges apart.
     *  3. A block whose triangles are not connected through shared edges
     *     (any block, not only a cracked one) becomes several blocks: the part
     * that holds the block's lowest-index cell keeps the block's index and
     * name, each other part (in the order of its lowest cell) gets the next
     * free block index and the name "<name>.<k>" with the smallest k >= 1 that
     * no block has yet.
     *  4. The new mesh is checked (check()) and the triangulation is
     *     rebuilt in place, as in build(): the Triangulation object stays
     *     the same, so a DoFHandler attached to it stays attached, but
     *     deal.II clears it (its degrees of freedom are gone) and it needs
     *     distribute_dofs() again. Copy what the transfer needs from the
     *     old DoFHandler (cell degrees of freedom, vertex degrees of
     *     freedom) before calling crack(); see state_transfer.
     * The crack faces are added to get_block_mesh().crack_edges.
     *
     * Cost: proportional to the number of cells and vertices, times a log
     * for the sorts in split_vertices_along_edges() and check(); no step
     * looks at pairs of cells or vertices. The rebuild of the
     * triangulation dominates (doc/fracture_mesh.md has timings).
     *
     * With @p refine, the cracked mesh is refined (as refine() does, with
     * the size bound that @p refine makes from it) before the one check and
     * rebuild; CrackResult::refined says how.
     *
     * @param edges Edges to crack, as pairs of vertex indices of the
     *   current mesh, in either order.
     * @return The maps from the old mesh to the new one.
     */
    CrackResult
    crack(const std::vector<std::array<unsigned int, 2>> &edges,
          const RefineAfterCrack                         &refine = {});

    /**
     * Refine the mesh by longest-edge bisection until the longest edge of
     * every cell is at most @p size_bound(block, centroid)
     * (refinement::bisect_to_size(): new vertices are edge midpoints in
     * the present and the initial geometry, the two faces of an open crack
     * are bisected together), check it in both geometries and rebuild the
     * triangulation
     * as crack() does (the DoFHandler needs distribute_dofs() again). A
     * bisected cell keeps its index for one half and the other half is
     * appended; blocks and materials stay, a bisected crack face becomes
     * two in get_block_mesh().crack_edges. If no cell is too
     * large, nothing changes (no rebuild).
     *
     * @param max_cells Refuse (ExcMessage, mesh unchanged) to make more
     *   cells than this.
     */
    refinement::RefineResult
    refine(const RefineAfterCrack::SizeBound &size_bound,
           const unsigned int                 max_cells);

    /**
     * Whether the edge between vertices @p a and @p b (in either order) is
     * a crack face: an edge cracked by crack() or a face of a pre-existing
     * crack of the scene (get_block_mesh().crack_edges). A crack whose two
     * tips lie inside the block keeps both vertices, so its edge is still
     * shared by two triangles and looks like an interior edge to everything
     * that only sees triangles (deal.II's faces, boundary_edges(),
     * fracture::find_interior_edges()); callers that pick edges to crack
     * must skip such edges. O(log n).
     */
    bool
    is_cracked(const unsigned int a, const unsigned int b) const;

    /**
     * Move every vertex by the given displacement (updated Lagrangian).
     */
    void
    move_vertices(const std::vector<Tensor<1, 2>> &displacement);

    /**
     * Move vertices @p moved to @p position (present geometry) and give
     * them the initial positions @p initial_position: the vertex now stands
     * for another point of the material (a crack tip's mesh aligned to
     * its path, fracture::plan_crack_advance()). The triangles stay the
     * same; the caller makes sure none turns inside out, and carries the
     * state to the new positions (state_transfer::interpolate_moved()).
     */
    void
    relocate_vertices(const std::vector<unsigned int> &moved,
                      const std::vector<Point<2>>     &position,
                      const std::vector<Point<2>>     &initial_position);

    /** Put every vertex at the given position, exactly. */
    void
    set_vertices(const std::vector<Point<2>> &vertices);

    /**
     * The position of every vertex when the scene was built (a vertex that
     * a crack created: that of the vertex it was copied from).
     */
    const std::vector<Point<2>> &
    get_initial_vertices() const
    {
      return initial_vertices;
    }

    /**
     * Call @p setup with every vertex at its initial position, then put
     * them back where they are, exactly: what is found by position in the
     * `.prm` (constraints, loads, bolts, measure points) is found on the
     * scene's initial geometry, the same after any crack and any restart.
     */
    template <typename Function>
    void
    on_initial_geometry(const Function &setup)
    {
      const std::vector<Point<2>> present = block_mesh.vertices;
      set_vertices(initial_vertices);
      setup();
      set_vertices(present);
    }

    /**
     * Write the mesh to a checkpoint, or read it from one (Archive): its
     * cells, blocks, crack faces and initial vertex positions. A mesh read
     * stands at its initial geometry; the present positions are the
     * caller's state (set_vertices()).
     */
    template <class Archive>
    void
    serialize(Archive &ar)
    {
      ar &block_mesh.triangles &block_mesh.cell_block &block_mesh
        .cell_material &block_mesh.block_names &block_mesh
        .crack_edges                           &initial_vertices;
      if (ar.loading())
        {
          geometry::BlockMesh mesh = block_mesh;
          mesh.vertices            = initial_vertices;
          install(std::move(mesh));
        }
    }

    /**
     * Whether moving the vertices by @p displacement would turn a cell
     * inside out (or flat): the sign of its area changes.
     */
    bool
    inverts_a_cell(const std::vector<Tensor<1, 2>> &displacement) const;

    /** Smallest and largest coordinates of all vertices. */
    std::pair<Point<2>, Point<2>>
    bounding_box() const;

    /**
     * The active cell that contains @p p (on its boundary counts) and the
     * point's coordinates on the reference triangle, found from barycentric
     * coordinates on the current vertex positions. Returns
     * numbers::invalid_unsigned_int as cell if no cell contains @p p.
     * Linear in the number of cells: meant for setup, not for time steps.
     */
    std::pair<unsigned int, Point<2>>
    locate(const Point<2> &p) const;

    /** Total area of all cells. */
    double
    area() const;

    /**
     * Check the mesh: counter-clockwise triangles of positive area, no edge
     * shared by more than two triangles (no two triangles running through
     * an edge in the same direction), no duplicate triangle, every vertex
     * used, no vertex shared by two blocks. Throws ExcMessage naming the
     * first offending cell, edge or vertex. O(n log n) for n cells (one
     * sort); it runs after every crack.
     */
    static void
    check(const geometry::BlockMesh &mesh);

  private:
    /**
     * Build the triangulation from @p mesh, which check() has accepted, and
     * take the arrays over. The Triangulation object stays the same.
     */
    void
    install(geometry::BlockMesh &&mesh);

    /// The same object for the mesh's life (a DoFHandler stays attached).
    std::unique_ptr<Triangulation<2>> triangulation;
    geometry::BlockMesh               block_mesh;
    std::vector<unsigned int>         cell_block;
    std::vector<std::string>          block_names;
    /// Keys (smaller vertex << 32 | larger vertex) of the edges in
    /// block_mesh.crack_edges, sorted.
    std::vector<std::uint64_t> crack_keys;
    /// See get_initial_vertices().
    std::vector<Point<2>> initial_vertices;
  };

  /**
   * Turn a triangulation of triangles into plain arrays, with one block per
   * connected group of cells of equal material id, and vertices split
   * between blocks.
   */
  geometry::BlockMesh
  to_block_mesh(const Triangulation<2> &triangulation,
                const std::string      &name_prefix);
} // namespace ndda

#endif
