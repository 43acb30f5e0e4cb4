// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_mesh_crackable_mesh_h
#define ndda_mesh_crackable_mesh_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <deal.II/grid/tria.h>

#include <ndda/geometry/block_mesh.h>

#include <string>
#include <vector>

namespace ndda
{
  using namespace dealii;

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
   * Later: the topology needed by contact and fracture (boundary loops,
   * cracked edges, node splitting and rebuild) lives here as well.
   *
   * @ingroup mesh
   */
  class CrackableMesh
  {
  public:
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
      return triangulation;
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
     * Move every vertex by the given displacement (updated Lagrangian).
     */
    void
    move_vertices(const std::vector<Tensor<1, 2>> &displacement);

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
    Triangulation<2>          triangulation;
    geometry::BlockMesh       block_mesh;
    std::vector<unsigned int> cell_block;
    std::vector<std::string>  block_names;
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
