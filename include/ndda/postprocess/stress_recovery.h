// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_postprocess_stress_recovery_h
#define ndda_postprocess_stress_recovery_h

#include <deal.II/base/quadrature.h>
#include <deal.II/base/symmetric_tensor.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/mapping.h>

#include <deal.II/lac/vector.h>

#include <array>
#include <vector>

namespace ndda
{
  template <int dim>
  class Simulator;

  namespace postprocess
  {
    using namespace dealii;

    /**
     * Nodal stresses recovered from the stresses at the quadrature points:
     * the L2 projection of each component onto the scalar element of the
     * displacement (FE_SimplexP(k): the element's own space), on the
     * present geometry. The mesh has separate nodes on the two sides of
     * every crack face and between blocks, so the projected field is
     * continuous within each piece and never averages across them.
     *
     * A cell mean is the stress near the cell's centroid: at a peak on a
     * boundary (a hole, a notch) it lies a third of a cell inside, and
     * with P2 it throws away the stress's variation in the cell. The
     * projection keeps the element's order (it reproduces a stress that
     * is a polynomial of the element's degree exactly) and gives values at
     * the nodes, which the output draws with the element's subdivisions
     * (doc/theory.md, "Nodal stresses").
     *
     * The consistent mass matrix of the scalar element (with
     * @p mass_quadrature) is solved by CG with a Jacobi preconditioner
     * (its condition number does not grow with the mesh's grading). The
     * stresses are known at the points of @p cell_quadrature only; in
     * each cell they are fitted (least squares, unit cell) by the complete
     * polynomial of the highest degree those points determine (a constant
     * for P1's one point, P2's linear stress from its three) and
     * integrated with the mass quadrature, so that a stress of that degree
     * is projected exactly.
     *
     * For a linear element (three dofs per cell, one at each vertex) the
     * projection of one constant a cell gains nothing at a boundary, so
     * by default the projected values are then replaced by the
     * superconvergent patch recovery of Zienkiewicz and Zhu (1992): at
     * every node inside a piece a linear stress is fitted by least squares
     * to the stresses of the cells around the node (at their quadrature
     * points) and evaluated at the node; a node on the boundary (an outer
     * edge, a hole, a crack face) takes the mean of the fits of the inner
     * nodes whose cells touch it, or its own fit if it has none, or keeps
     * the projected value if its own cells cannot determine a linear fit
     * (doc/theory.md, "Nodal stresses"). Patches are made of the cells
     * that share the node's dof, so they never reach across a crack or
     * into another block.
     *
     * @ingroup postprocess
     */
    class StressRecovery
    {
    public:
      using Stress = SymmetricTensor<2, 2>;

      /** How the nodal values of a linear element are found. */
      enum class LinearMethod
      {
        /// The L2 projection alone.
        projection,
        /// Zienkiewicz-Zhu patch recovery, the projection as fallback.
        patch_recovery
      };

      /**
       * @param linear_method For linear elements: patch recovery (the
       *   default) or the L2 projection. Other elements always use the
       *   projection.
       */
      explicit StressRecovery(
        const LinearMethod linear_method = LinearMethod::patch_recovery)
        : linear_method(linear_method)
      {}

      /**
       * Project @p stresses, given at the points of @p cell_quadrature of
       * every active cell of @p displacement_dofs's triangulation (by
       * active cell index), onto the scalar element of
       * @p displacement_dofs (its base element 0), on the geometry of
       * @p mapping.
       */
      void
      recover(const DoFHandler<2>                    &displacement_dofs,
              const Mapping<2>                       &mapping,
              const Quadrature<2>                    &cell_quadrature,
              const Quadrature<2>                    &mass_quadrature,
              const std::vector<std::vector<Stress>> &stresses);

      /** recover() the present stresses of @p simulator, on its present
       * geometry. */
      void
      recover(const Simulator<2> &simulator);

      /** The scalar element's dofs of the recovered field. */
      const DoFHandler<2> &
      get_dof_handler() const
      {
        return dof_handler;
      }

      /** The components xx, yy and xy, one value per dof. */
      const std::array<Vector<double>, 3> &
      get_components() const
      {
        return components;
      }

      /** The recovered stress at dof @p i. */
      Stress
      at_dof(const types::global_dof_index i) const;

      /** The recovered stress at vertex @p v of @p cell. */
      Stress
      at_vertex(const DoFHandler<2>::active_cell_iterator &cell,
                const unsigned int                         v) const;

      /** CG iterations of the last recover(), the most of the three
       * components. */
      unsigned int
      n_iterations() const
      {
        return iterations;
      }

      /** How many nodes of the last recover() kept the projected value
       * because no patch determined a linear fit (0 for other elements). */
      unsigned int
      n_projected_nodes() const
      {
        return projected_nodes;
      }

    private:
      void
      recover_by_patches(const Mapping<2>                       &mapping,
                         const Quadrature<2>                    &quadrature,
                         const std::vector<std::vector<Stress>> &stresses);

      LinearMethod                  linear_method;
      unsigned int                  projected_nodes = 0;
      DoFHandler<2>                 dof_handler;
      std::array<Vector<double>, 3> components;
      unsigned int                  iterations = 0;
    };
  } // namespace postprocess
} // namespace ndda

#endif
