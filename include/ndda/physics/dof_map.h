// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_physics_dof_map_h
#define ndda_physics_dof_map_h

#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/lac/vector.h>

#include <array>
#include <vector>

namespace ndda
{
  /**
   * The degrees of freedom of the vector finite element space as plain
   * index arrays, for the loops of the time step (deal.II's iterators and
   * get_dof_indices() cost more than the arithmetic of a P1 cell), and as
   * the read-only view that contacts, loads and constraints get of the
   * space. A node is a support point of the scalar element (a vertex, or
   * for P2 an edge midpoint), with its x and y dofs.
   *
   * @ingroup physics
   */
  struct DofMap
  {
    using index = dealii::types::global_dof_index;

    /** Rebuild from @p dof_handler (after distribute_dofs()). */
    void
    reinit(const dealii::DoFHandler<2> &dof_handler);

    /** The dofs of active cell @p c, dofs_per_cell of them. */
    const index *
    dofs_of_cell(const unsigned int c) const
    {
      return cell_dofs.data() + std::size_t(c) * dofs_per_cell;
    }

    /** The triangulation's indices of the vertices of active cell @p c,
     * vertices_per_cell of them. */
    const unsigned int *
    vertices_of_cell(const unsigned int c) const
    {
      return cell_vertices.data() + std::size_t(c) * vertices_per_cell;
    }

    unsigned int
    n_cells() const
    {
      return dofs_per_cell == 0 ? 0 : cell_dofs.size() / dofs_per_cell;
    }

    /// The vector element (FESystem) of the space.
    const dealii::FiniteElement<2> *fe = nullptr;
    /// Number of dofs of the space.
    unsigned int n_dofs = 0;
    /// Dofs of a cell.
    unsigned int dofs_per_cell = 0;
    /// Dof indices of every cell, cell after cell.
    std::vector<index> cell_dofs;
    /// Vertices of a cell.
    unsigned int vertices_per_cell = 0;
    /// The triangulation's vertex indices of every cell, cell after cell
    /// (a crack renumbers them without moving the vertices).
    std::vector<unsigned int> cell_vertices;
    /// Vector component of each local dof.
    std::vector<unsigned int> local_component;
    /// The (x, y) dofs of every vertex of the triangulation.
    std::vector<std::array<index, 2>> vertex_dofs;
    /// The (x, y) dofs of every node (vertices and, for P2, edge nodes).
    std::vector<std::array<index, 2>> node_dofs;
    /// Node of every dof.
    std::vector<unsigned int> dof_to_node;

    /** The (x, y) values of the dof vector @p v at every vertex. */
    std::vector<dealii::Tensor<1, 2>>
    vertex_values(const dealii::Vector<double> &v) const;

    /** The largest length of the vectors of @p v at the vertices. */
    double
    max_vertex_norm(const dealii::Vector<double> &v) const;
  };
} // namespace ndda

#endif
