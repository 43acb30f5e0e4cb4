// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_time_dda_h
#define ndda_time_dda_h

#include <ndda/time/time_integrator.h>

namespace ndda
{
  namespace time
  {
    /**
     * Shi's DDA scheme (thesis 3.7, 3.15): constant acceleration over the
     * step, d = v0 dt + a dt^2 / 2, with the acceleration taken at the
     * step's end; v1 = 2 d / dt - v0. The step solves
     * (K + 2/dt^2 M) d = f + 2/dt M v0. First order, unconditionally
     * stable, and numerically damped (doc/theory.md).
     *
     * @ingroup time
     */
    class DDA : public TimeIntegrator
    {
    public:
      double
      mass_coefficient(const double dt) const override;

      void
      add_inertia_terms(const SparseMatrix<double> &mass,
                        const KinematicState       &start,
                        const double                dt,
                        Vector<double>             &rhs) const override;

      void
      update(const Vector<double>       &d,
             const double                dt,
             const SparseMatrix<double> &mass,
             const Vector<double>       &contact_correction,
             KinematicState             &state) const override;
    };
  } // namespace time
} // namespace ndda

#endif
