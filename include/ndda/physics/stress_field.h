// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_physics_stress_field_h
#define ndda_physics_stress_field_h

#include <deal.II/base/symmetric_tensor.h>

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <ndda/mesh/crackable_mesh.h>
#include <ndda/physics/dof_map.h>
#include <ndda/physics/element_cache.h>
#include <ndda/physics/physics_parameters.h>

#include <utility>
#include <vector>

namespace ndda
{
  /**
   * The stresses of a scene, one per point of the cell quadrature of every
   * active cell, and what a step does with them: the objective update
   * over an increment (turn with the cell's spin, then the constitutive
   * law's update), the internal force and the strain energy they hold.
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
     * @p cell_material; with @p rotate_with_spin, stresses turn with the
     * spin (Control/Rotate with spin). The objects are referenced, not
     * copied.
     */
    void
    initialize(const ElementCache<2>           &element_cache,
               const DofMap                    &dof_map,
               const parameters::Materials     &materials,
               const std::vector<unsigned int> &cell_material,
               const bool                       rotate_with_spin);

    /** @p n_cells cells of @p n_points zero stresses each. */
    void
    reinit(const unsigned int n_cells, const unsigned int n_points);

    unsigned int
    n_cells() const
    {
      return stress.size();
    }

    std::vector<Stress> &
    operator[](const unsigned int cell)
    {
      return stress[cell];
    }

    const std::vector<Stress> &
    operator[](const unsigned int cell) const
    {
      return stress[cell];
    }

    /** The whole field, cell by cell (for the state transfer of a crack). */
    std::vector<std::vector<Stress>> &
    cells()
    {
      return stress;
    }

    const std::vector<std::vector<Stress>> &
    cells() const
    {
      return stress;
    }

    /**
     * The stresses @p sigma of cell @p cell at the end of a step with
     * increment @p d: on entry the start stresses; turned by the cell's
     * rotation in the increment (if stresses turn with the spin), then
     * updated by the constitutive law with the increment's strain.
     */
    void
    advance(const unsigned int    cell,
            const Vector<double> &d,
            std::vector<Stress>  &sigma) const;

    /** advance() every cell's stresses. */
    void
    advance(const Vector<double> &d);

    /** Area-weighted mean of the stresses @p sigma at the points of
     * @p cell. */
    Stress
    mean(const unsigned int cell, const std::vector<Stress> &sigma) const;

    /** Area-weighted mean stress of cell @p cell. */
    Stress
    mean(const unsigned int cell) const
    {
      return mean(cell, stress[cell]);
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

    /** Area of every cell (the sum of its quadrature weights). */
    std::vector<double>
    cell_areas() const;

    /**
     * Set @p force to the internal force t int B^T sigma (thesis 3.25, with
     * the accumulated stress in place of the initial stress) and return
     * the elastic energy the stresses hold (the law's energy density
     * integrated, J).
     */
    double
    internal_force(Vector<double> &force) const;

    /** Rotation (rad) of cell @p cell in the increment @p d times its area,
     * and its area. */
    std::pair<double, double>
    cell_rotation(const unsigned int cell, const Vector<double> &d) const;

  private:
    const ElementCache<2>           *element_cache    = nullptr;
    const DofMap                    *dof_map          = nullptr;
    const parameters::Materials     *materials        = nullptr;
    const std::vector<unsigned int> *cell_material    = nullptr;
    bool                             rotate_with_spin = false;

    std::vector<std::vector<Stress>> stress;
  };

  /**
   * Turn the velocity @p velocity and inertia force @p inertia_force of
   * each block of @p mesh relative to its centre of mass by the block's
   * rotation in the increment @p d (area-weighted mean of its cells'
   * rotations from @p stresses), with the row sums of @p mass as nodal
   * masses. The small-rotation update moves points along straight lines:
   * without this, a spinning block would not turn its velocity
   * (doc/theory.md).
   */
  void
  rotate_block_motion(const CrackableMesh        &mesh,
                      const DofMap               &dof_map,
                      const StressField          &stresses,
                      const SparseMatrix<double> &mass,
                      const Vector<double>       &d,
                      Vector<double>             &velocity,
                      Vector<double>             &inertia_force);
} // namespace ndda

#endif
