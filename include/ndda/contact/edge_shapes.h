// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_contact_edge_shapes_h
#define ndda_contact_edge_shapes_h

#include <deal.II/fe/fe.h>

#include <array>
#include <vector>

namespace ndda
{
  namespace contact
  {
    /**
     * The cells' shape functions along the three edges of the reference
     * triangle: for the edge that starts at local vertex k, the local
     * dofs whose functions do not vanish on it, and their values at
     * degree + 1 equispaced points, which interpolate them exactly
     * (doc/contact.md, "Kernels"). ContactHandler makes the
     * options of its contacts with them.
     *
     * @ingroup contact
     */
    class EdgeShapes
    {
    public:
      /**
       * Sample the shape functions of @p fe; checks the interpolation
       * at two more points and falls back to direct evaluation on all
       * dofs where it does not hold.
       */
      void
      initialize(const dealii::FiniteElement<2> &fe);

      /** The local dofs of the edge from local vertex @p k. */
      const std::vector<unsigned int> &
      dofs(const unsigned int k) const
      {
        return edge_dofs[k];
      }

      /**
       * The values at the point @p c in [0, 1] along the edge from
       * local vertex @p k of the functions of dofs(k), to @p values.
       */
      void
      values(const unsigned int k, const double c, double *values) const;

    private:
      /// Sampled up to degree 7; higher degrees are evaluated directly.
      static constexpr unsigned int max_points = 8;

      const dealii::FiniteElement<2>          *fe       = nullptr;
      unsigned int                             n_points = 0;
      bool                                     sampled  = false;
      std::array<std::vector<unsigned int>, 3> edge_dofs;
      /// Per edge, per dof of edge_dofs, n_points values.
      std::array<std::vector<double>, 3> samples;
    };
  } // namespace contact
} // namespace ndda

#endif
