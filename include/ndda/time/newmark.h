// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_time_newmark_h
#define ndda_time_newmark_h

#include <ndda/time/time_integrator.h>

namespace ndda
{
  namespace time
  {
    /**
     * Newmark's average acceleration method (beta = 1/4, gamma = 1/2):
     * d = v0 dt + (a0 + a1) dt^2 / 4, v1 = 2 d / dt - v0. The step solves
     * (K + 4/dt^2 M) d = f + 4/dt M v0 + M a0. Second order and without
     * numerical damping; forces act as the mean of their start and end
     * values, so contacts that open or close within a step correct M a0
     * (doc/theory.md, doc/contact.md).
     *
     * @ingroup time
     */
    class Newmark : public TimeIntegrator
    {
    public:
      double
      mass_coefficient(const double dt) const override;

      void
      add_inertia_terms(const SparseMatrix<double> &mass,
                        const KinematicState       &start,
                        const double                dt,
                        Vector<double>             &rhs) const override;

      double
      contact_start_weight() const override;

      bool
      needs_initial_acceleration() const override;

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
