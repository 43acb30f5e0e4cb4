// SPDX-License-Identifier: GPL-3.0-or-later

#include <ndda/time/newmark.h>

namespace ndda
{
  namespace time
  {
    double
    Newmark::mass_coefficient(const double dt) const
    {
      return 4. / (dt * dt);
    }



    void
    Newmark::add_inertia_terms(const SparseMatrix<double> &mass,
                               const KinematicState       &start,
                               const double                dt,
                               Vector<double>             &rhs) const
    {
      Vector<double> mv(start.velocity);
      mv *= 4. / dt;
      mass.vmult_add(rhs, mv);
      rhs += start.inertia_force;
    }



    double
    Newmark::contact_start_weight() const
    {
      return 0.5;
    }



    bool
    Newmark::needs_initial_acceleration() const
    {
      return true;
    }



    void
    Newmark::update(const Vector<double>       &d,
                    const double                dt,
                    const SparseMatrix<double> &mass,
                    const Vector<double>       &contact_correction,
                    KinematicState             &state) const
    {
      // M a1 = 4 / dt^2 M (d - dt v0) - M a0, where M a0 leaves out the
      // start forces of contacts that opened in this step
      // (contact::ContactHandler::newmark_correction()).
      Vector<double> a(d), ma(d.size());
      a.add(-dt, state.velocity);
      a *= 4. / (dt * dt);
      mass.vmult(ma, a);
      ma -= state.inertia_force;
      if (contact_correction.size() == ma.size())
        ma -= contact_correction;
      state.inertia_force = ma;
      state.velocity *= -1.;
      state.velocity.add(2. / dt, d);
    }



    NDDA_REGISTER_PLUGIN(
      TimeIntegrator,
      Newmark,
      "Newmark",
      "Newmark's average acceleration method (beta = 1/4, gamma = 1/2). "
      "Second order, no numerical damping; unstable with stiff contacts in "
      "some scenes (doc/stability/stability.md, doc/contact.md).")
  } // namespace time
} // namespace ndda
