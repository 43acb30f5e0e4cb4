// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_mesh_state_transfer_h
#define ndda_mesh_state_transfer_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/point.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/types.h>

#include <deal.II/fe/fe.h>

#include <deal.II/lac/vector.h>

#include <ndda/mesh/refinement.h>

#include <array>
#include <string>
#include <vector>

namespace ndda
{
  /**
   * Carry state across a node split (CrackableMesh::crack()). Cells keep
   * their index and the order of their vertices, so per-cell state stays
   * where it is; a vertex of the new mesh takes the state of the vertex it
   * was copied from; a degree of freedom of the new mesh takes the value of
   * the degree of freedom at the same place (same cell, same local index)
   * of the old mesh. All three are exact copies: the two faces of a new
   * crack start with the same displacement, velocity and stress history.
   *
   * @ingroup mesh
   */
  namespace state_transfer
  {
    /**
     * Per-vertex state of the new mesh: the new vertex v gets
     * @p old_values[new_to_old[v]].
     *
     * @param old_values One value per vertex of the old mesh.
     * @param new_to_old For every vertex of the new mesh, the vertex of the
     *   old mesh it comes from (CrackResult::vertex_origin).
     */
    template <typename T>
    std::vector<T>
    transfer_vertex_data(const std::vector<T>            &old_values,
                         const std::vector<unsigned int> &new_to_old)
    {
      std::vector<T> new_values;
      new_values.reserve(new_to_old.size());
      for (const unsigned int v : new_to_old)
        {
          AssertIndexRange(v, old_values.size());
          new_values.push_back(old_values[v]);
        }
      return new_values;
    }

    /**
     * A vector of degrees of freedom on the new mesh from one on the old
     * mesh, for any element (P1, P2, FESystem of them): for every cell c
     * and local index i, new_values[new_cell_dofs[c n + i]] =
     * old_values[old_cell_dofs[c n + i]], n being the number of degrees of
     * freedom per cell. A degree of freedom of the new mesh lies in one fan
     * of the old one, where all cells around it referred to the same old
     * degree of freedom, so every write of it writes the same value. The
     * degrees of freedom on a cracked edge (P2) or at a split vertex get
     * copies.
     *
     * Rebuilding the triangulation clears a DoFHandler attached to it
     * (deal.II connects DoFHandler::clear() to the triangulation's clear
     * signal), so @p old_cell_dofs must be copied from the DoFHandler before
     * CrackableMesh::crack() is called, for example as the simulator's
     * cell_dof_indices cache.
     *
     * @param old_cell_dofs The degrees of freedom of every cell of the old
     *   mesh, cell after cell in active cell index order.
     * @param old_values Values on the old mesh.
     * @param new_cell_dofs The same for the new mesh, after
     *   DoFHandler::distribute_dofs(); same length as @p old_cell_dofs.
     * @param new_values Values on the new mesh; must have the new number
     *   of degrees of freedom.
     */
    template <typename VectorType>
    void
    transfer_dof_values(
      const std::vector<dealii::types::global_dof_index> &old_cell_dofs,
      const VectorType                                   &old_values,
      const std::vector<dealii::types::global_dof_index> &new_cell_dofs,
      VectorType                                         &new_values)
    {
      AssertThrow(old_cell_dofs.size() == new_cell_dofs.size(),
                  dealii::ExcMessage(
                    "transfer_dof_values: the old and new meshes have "
                    "different numbers of cell degrees of freedom (" +
                    std::to_string(old_cell_dofs.size()) + " and " +
                    std::to_string(new_cell_dofs.size()) +
                    "); node splitting keeps the cells and the element."));
      for (std::size_t k = 0; k < new_cell_dofs.size(); ++k)
        new_values[new_cell_dofs[k]] = old_values[old_cell_dofs[k]];
    }

    /**
     * Carry dof vectors across a move of vertices that keeps the triangles
     * (CrackableMesh::relocate_vertices()): every degree of freedom whose
     * support point moves takes the value of the old field (the old
     * vertices, the same dof values) at its new support point, found in
     * the triangles around the moved vertices; all others keep their
     * value. Exact for fields the element represents on the old mesh
     * restricted to where the new support points fall; a node at a moved
     * vertex gets the linear (P1) or quadratic (P2) interpolant of the old
     * field there. The element must have support points; cells map
     * linearly (the reference triangle's vertices 0, 1, 2 to the cell's).
     *
     * @param cell_dofs Dofs of every cell, cell after cell (DofMap).
     * @param moved The moved vertices; @p old_vertices and @p new_vertices
     *   are all positions before and after.
     * @param vectors The dof vectors to carry, changed in place.
     */
    void
    interpolate_moved(
      const dealii::FiniteElement<2>                     &fe,
      const std::vector<dealii::types::global_dof_index> &cell_dofs,
      const std::vector<std::array<unsigned int, 3>>     &triangles,
      const std::vector<unsigned int>                    &moved,
      const std::vector<dealii::Point<2>>                &old_vertices,
      const std::vector<dealii::Point<2>>                &new_vertices,
      const std::vector<dealii::Vector<double> *>        &vectors);

    /**
     * Dof vectors on a mesh refined by bisection
     * (refinement::bisect_to_size()), from the mesh before: a cell that
     * was not bisected copies its values by local index (as
     * transfer_dof_values()), a part of a bisected cell takes the old
     * cell's field at its support points. Exact for every field of the
     * element on the old mesh (P1 and P2 alike: the parts of a straight
     * triangle hold its polynomials), so nothing the solution held is lost
     * and the values written twice (dofs shared by two cells) agree.
     *
     * The old mesh may itself be a node split of the one @p old_cell_dofs
     * were taken on (CrackableMesh::crack() keeps cell indices and local
     * dof order): a crack and the refinement after it are carried in one
     * call.
     *
     * @param old_cell_dofs Dofs of every old cell, cell after cell.
     * @param new_cell_dofs The same for the refined mesh.
     * @param old_vectors, new_vectors Pairs of vectors: old values, and
     *   vectors of the new number of dofs to fill.
     */
    void
    transfer_refined(
      const dealii::FiniteElement<2>                     &fe,
      const std::vector<dealii::types::global_dof_index> &old_cell_dofs,
      const refinement::RefineResult                     &refined,
      const std::vector<dealii::types::global_dof_index> &new_cell_dofs,
      const std::vector<const dealii::Vector<double> *>  &old_vectors,
      const std::vector<dealii::Vector<double> *>        &new_vectors);

    /**
     * Per-point cell values (stresses at the cell quadrature's points) on
     * a mesh refined by bisection, in place: a part of a bisected cell
     * takes the polynomial of degree @p degree that fits the old cell's
     * values in least squares (weighted by the quadrature), evaluated at
     * its own points. Degree 0 gives the old cell's mean; for P2 (degree
     * 1, three points) the fit passes through the three values, so a
     * stress linear in the cell (what a P2 step adds) is carried exactly.
     * Cells not bisected keep their values.
     */
    void
    transfer_refined(
      const dealii::Quadrature<2>                             &quadrature,
      const unsigned int                                       degree,
      const refinement::RefineResult                          &refined,
      std::vector<std::vector<dealii::SymmetricTensor<2, 2>>> &values);
  } // namespace state_transfer
} // namespace ndda

#endif
