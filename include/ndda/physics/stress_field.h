// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_physics_stress_field_h
#define ndda_physics_stress_field_h

#include <deal.II/base/array_view.h>
#include <deal.II/base/symmetric_tensor.h>

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <ndda/mesh/crackable_mesh.h>
#include <ndda/parallel/owned_cells.h>
#include <ndda/physics/dof_map.h>
#include <ndda/physics/element_cache.h>
#include <ndda/physics/physics_parameters.h>

#include <utility>
#include <vector>

namespace ndda
{
  /**
   * The stresses of a scene (Cauchy stresses in the global frame), one per
   * point of the cell quadrature of every active cell, and what a step
   * does with them: the objective update over an increment (the step's
   * deformation gradient split into its exact rotation, which turns the
   * stress, and its stretch, the strain the constitutive law is given),
   * the internal force on the present geometry and the strain energy they
   * hold (doc/theory.md, "Finite rotation").
   *
   * @ingroup physics
   */
  class StressField
  {
  public:
    using Stress = SymmetricTensor<2, 2>;

    /**
     * Work on the cells of @p element_cache with the dofs of @p dof_map,
     * the law and materials of @p materials, the material id of each cell
     * @p cell_material, on the present geometry of @p triangulation (its
     * vertices move with the run). With @p owned_cells, the processes
     * among which it splits the cells share the per-cell work of
     * internal_force() and advance_with_internal_force() (each computes
     * its own cells, and then every process has every cell's stresses
     * and the whole force); without it, this process does every cell. The
     * objects are referenced, not copied.
     */
    void
    initialize(const ElementCache<2>           &element_cache,
               const DofMap                    &dof_map,
               const parameters::Materials     &materials,
               const std::vector<unsigned int> &cell_material,
               const Triangulation<2>          &triangulation,
               const OwnedCells                *owned_cells = nullptr);

    /** @p n_cells cells of @p n_points zero stresses each. */
    void
    reinit(const unsigned int n_cells, const unsigned int n_points);

    unsigned int
    n_cells() const
    {
      return n_active_cells;
    }

    /** The number of stresses of each cell (the cell quadrature's points). */
    unsigned int
    points_per_cell() const
    {
      return n_points;
    }

    /** The stresses of cell @p cell, one per point. */
    ArrayView<Stress>
    operator[](const unsigned int cell)
    {
      return {stress.data() + std::size_t(cell) * n_points, n_points};
    }

    ArrayView<const Stress>
    operator[](const unsigned int cell) const
    {
      return {stress.data() + std::size_t(cell) * n_points, n_points};
    }

    /**
     * The stresses of all cells in one array: points_per_cell() of
     * cell 0, then of cell 1, and so on. The loops of every step stream
     * through it.
     */
    const std::vector<Stress> &
    values() const
    {
      return stress;
    }

    /** The stresses cell by cell (for the state transfer of a crack and
     * the nodal recovery). */
    std::vector<std::vector<Stress>>
    by_cell() const;

    /** Set the stresses cell by cell: as many cells as given, each with
     * the same number of points. */
    void
    set_by_cell(const std::vector<std::vector<Stress>> &cells);

    /**
     * The stresses @p sigma of cell @p cell at the end of a step with
     * increment @p d from the present geometry: on entry the start
     * stresses. At each point the step's deformation gradient
     * F = I + dd/dx = V R is split; the stress is turned by R (exactly),
     * then updated by the constitutive law with the strain V - I. A cell
     * that @p d does not move at all keeps @p sigma as it is.
     */
    void
    advance(const unsigned int    cell,
            const Vector<double> &d,
            ArrayView<Stress>     sigma) const;

    /** advance() every cell's stresses. */
    void
    advance(const Vector<double> &d);

    /**
     * advance() every cell's stresses by the increment @p d and set
     * @p force to their internal force on the step's end geometry (the
     * present vertices moved by @p d's values at them), in one pass over
     * the cells; return the elastic energy they hold. The same as
     * advance(), moving the vertices, then internal_force(), to the last
     * bit.
     */
    double
    advance_with_internal_force(const Vector<double> &d, Vector<double> &force);

    /** Area-weighted mean of the stresses @p sigma at the points of
     * @p cell. */
    Stress
    mean(const unsigned int cell, const ArrayView<const Stress> &sigma) const;

    /** Area-weighted mean stress of cell @p cell. */
    Stress
    mean(const unsigned int cell) const
    {
      return mean(cell, (*this)[cell]);
    }

    /** Area-weighted mean stress of every cell. */
    std::vector<Stress>
    cell_means() const;

    /**
     * Area-weighted mean stress of every cell at the end of a step with
     * increment @p d (advance() on copies; the field is not changed).
     */
    std::vector<Stress>
    trial_cell_means(const Vector<double> &d) const;

    /** Present area of every cell (times the thickness). */
    std::vector<double>
    cell_areas() const;

    /**
     * Set @p force to the internal force t int_x B^T sigma on the present
     * geometry (thesis 3.25, with the accumulated stress in place of the
     * initial stress) and return the elastic energy the stresses hold (the
     * law's energy density integrated, J).
     */
    double
    internal_force(Vector<double> &force) const;

    /**
     * The rotation (rad) of cell @p cell in the increment @p d, the
     * curl of d on the present geometry, times the cell's present area;
     * and that area.
     */
    std::pair<double, double>
    cell_rotation(const unsigned int cell, const Vector<double> &d) const;

    /** Write the stresses to a checkpoint or read them (Archive). */
    template <class Archive>
    void
    serialize(Archive &ar)
    {
      ar &stress &n_active_cells &n_points;
    }

  private:
    /** Whether the increment @p d moves any node of cell @p c. */
    bool
    moves_in(const unsigned int c, const Vector<double> &d) const;

    /** The deformation gradient of cell @p cell since its element data
     * were computed (ElementCache::deformation_gradient()). */
    Tensor<2, 2>
    deformation_gradient(const unsigned int cell) const;

    /** The stresses @p sigma of cell @p c advanced by @p d (advance()),
     * @p F_inverse the inverse of its deformation_gradient(). */
    void
    advance_cell(const unsigned int    c,
                 const Vector<double> &d,
                 const Tensor<2, 2>   &F_inverse,
                 Stress               *sigma) const;

    /**
     * The internal force of the stresses @p sigma of cell @p c, whose
     * deformation gradient is @p F, into @p local_force (its n_points
     * times dofs_per_cell terms, point by point, in the order of the
     * cell's dofs); return their energy, @p compliance the inverse of the
     * tangent of its material.
     */
    double
    cell_force(const unsigned int           c,
               const Tensor<2, 2>          &F,
               const Stress                *sigma,
               const SymmetricTensor<4, 2> &compliance,
               double                      *local_force) const;

    /**
     * Set @p force to the sum of every cell's force and return the sum of
     * their energies, @p cell_force_of(c, local_force) giving cell c's
     * (as cell_force()); called on deal.II's threads, it must write only
     * what belongs to cell c. Each process computes its own cells
     * (owned_range()), and shares the terms with the others. The sums are
     * taken in cell order on one thread: the result does not depend on the
     * number of threads or processes.
     */
    template <typename CellForce>
    double
    sum_cell_forces(const CellForce &cell_force_of,
                    Vector<double>  &force) const;

    /** The cells whose per-cell work this process does: every cell
     * without OwnedCells. */
    std::pair<unsigned int, unsigned int>
    owned_range() const;

    /** The inverse of the tangent of every material (for the energy). */
    std::vector<SymmetricTensor<4, 2>>
    compliances() const;

    const ElementCache<2>           *element_cache = nullptr;
    const DofMap                    *dof_map       = nullptr;
    const parameters::Materials     *materials     = nullptr;
    const std::vector<unsigned int> *cell_material = nullptr;
    const Triangulation<2>          *triangulation = nullptr;
    const OwnedCells                *owned_cells   = nullptr;

    /// The stresses of all cells, n_points per cell (values()).
    std::vector<Stress> stress;
    unsigned int        n_active_cells = 0;
    unsigned int        n_points       = 0;

    /// Cells per task of the loops on threads.
    static constexpr unsigned int cell_grain_size = 2048;
    /// Scratch of sum_cell_forces(): every cell's force terms and energy.
    mutable std::vector<double> local_forces, local_energies;
  };

} // namespace ndda

#endif
