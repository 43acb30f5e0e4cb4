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
     * @ingroup postprocess
     */
    class StressRecovery
    {
    public:
      using Stress = SymmetricTensor<2, 2>;

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

    private:
      DoFHandler<2>                 dof_handler;
      std::array<Vector<double>, 3> components;
      unsigned int                  iterations = 0;
    };
  } // namespace postprocess
} // namespace ndda

#endif
