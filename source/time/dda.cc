// SPDX-License-Identifier: GPL-3.0-or-later

#include <ndda/time/dda.h>

namespace ndda
{
  namespace time
  {
    double
    DDA::mass_coefficient(const double dt) const
    {
      return 2. / (dt * dt);
    }



    void
    DDA::add_inertia_terms(const SparseMatrix<double> &mass,
                           const KinematicState       &start,
                           const double                dt,
                           Vector<double>             &rhs) const
    {
      Vector<double> mv(start.velocity);
      mv *= 2. / dt;
      mass.vmult_add(rhs, mv);
    }



    void
    DDA::update(const Vector<double> &d,
                const double          dt,
                const SparseMatrix<double> &,
                const Vector<double> &,
                KinematicState &state) const
    {
      // The scheme has no acceleration of its own: M a stays as it is
      // (zero).
      state.velocity *= -1.;
      state.velocity.add(2. / dt, d);
    }



    NDDA_REGISTER_PLUGIN(
      TimeIntegrator,
      DDA,
      "DDA",
      "Shi's scheme (thesis 3.7): constant acceleration within the step, "
      "taken at its end; v1 = 2 d / dt - v0. First order, unconditionally "
      "stable with stiff contacts, numerically damped (doc/theory.md).")
  } // namespace time
} // namespace ndda
