// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_time_generalized_alpha_h
#define ndda_time_generalized_alpha_h

#include <ndda/time/time_integrator.h>

namespace ndda
{
  namespace time
  {
    /**
     * The generalized-α method of Chung and Hulbert (1993): Newmark's
     * relations
     *
     *   d       = dt v0 + dt^2 ((1/2 - beta) a0 + beta a1),
     *   v1      = v0 + dt ((1 - gamma) a0 + gamma a1),
     *
     * with the equation of motion taken between the step's ends,
     * M ((1 - alpha_m) a1 + alpha_m a0) = (1 - alpha_f) r1 + alpha_f r0,
     * r the force f_ext - f_int + contact forces. From the spectral radius
     * at infinite frequency rho (`Spectral radius at infinity`, 0 to 1,
     * default 0):
     * alpha_m = (2 rho - 1) / (rho + 1), alpha_f = rho / (rho + 1),
     * gamma = 1/2 - alpha_m + alpha_f, beta = (1 - alpha_m + alpha_f)^2 / 4.
     * Second order for every rho; modes far above 1/dt are scaled by rho
     * per step, the resolved ones are barely damped. rho = 1 is Newmark's
     * average acceleration (the same increments and velocities).
     *
     * The step solves (K + c M) d = f_ext(t1) - f_int + the inertia terms,
     * the equation divided by 1 - alpha_f: c = (1 - alpha_m) /
     * ((1 - alpha_f) beta dt^2). KinematicState::inertia_force holds r0,
     * KinematicState::acceleration a0 (doc/theory.md, "Generalized-α").
     *
     * The acceleration a0 is not a(t0): with these parameters it is the
     * acceleration at t0 + (alpha_m - alpha_f) dt, a step before t0 at
     * rho = 0. Started with a(t0) under a sudden load, the step gives the
     * modes it does not resolve a velocity of about (a(t0) / 4) dt, an
     * energy of (omega dt)^2 / 16 times the static strain energy (25 times
     * at omega dt = 20). So the first step (KinematicState::starting) takes
     * the acceleration constant over the step instead, a1 = a0 =
     * 2 (d - dt v0) / dt^2, with M a0 = (1 - alpha_f) r1 + alpha_f r0.
     * That step loses energy, k d^2 (1/2 - alpha_f) for a spring k, gains
     * none at any rho, and keeps second order (doc/theory.md, "Start-up").
     *
     * @ingroup time
     */
    class GeneralizedAlpha : public TimeIntegrator
    {
    public:
      /** The scheme at the entry's default, rho = 0. */
      GeneralizedAlpha();

      static void
      declare_parameters(ParameterHandler &prm);

      void
      parse_parameters(ParameterHandler &prm) override;

      /** Set the spectral radius at infinity and the four parameters. */
      void
      set_spectral_radius(const double rho_infinity);

      double
      mass_coefficient(const double dt) const override;

      double
      first_step_mass_coefficient(const double dt) const override;

      void
      add_inertia_terms(const SparseMatrix<double> &mass,
                        const KinematicState       &start,
                        const double                dt,
                        Vector<double>             &rhs) const override;

      double
      contact_start_weight() const override;

      bool
      needs_initial_acceleration() const override;

      bool
      keeps_acceleration() const override;

      void
      update(const Vector<double>       &d,
             const double                dt,
             const SparseMatrix<double> &mass,
             const Vector<double>       &contact_correction,
             KinematicState             &state) const override;

    private:
      double alpha_m, alpha_f, beta, gamma;
    };
  } // namespace time
} // namespace ndda

#endif
