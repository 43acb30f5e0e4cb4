// SPDX-License-Identifier: GPL-3.0-or-later

#include <ndda/time/generalized_alpha.h>

namespace ndda
{
  namespace time
  {
    GeneralizedAlpha::GeneralizedAlpha()
    {
      set_spectral_radius(0.);
    }



    void
    GeneralizedAlpha::declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry(
        "Spectral radius at infinity",
        "0",
        dealii::Patterns::Double(0., 1.),
        "rho_inf, from 0 to 1: the factor by which the scheme scales, in "
        "every step, the modes far above 1/dt (penalty springs, the "
        "mesh's highest modes). 1 is Newmark's average acceleration (no "
        "damping at all); 0 (the default) removes them within a step; the "
        "modes the step resolves are kept to second order whatever its "
        "value. With contacts, values between 0 and 1 can gain energy "
        "(doc/theory.md, 'Generalized-alpha', measures 0, 0.5, 0.8, 1).");
    }



    void
    GeneralizedAlpha::parse_parameters(ParameterHandler &prm)
    {
      set_spectral_radius(prm.get_double("Spectral radius at infinity"));
    }



    void
    GeneralizedAlpha::set_spectral_radius(const double rho)
    {
      AssertThrow(rho >= 0. && rho <= 1.,
                  dealii::ExcMessage(
                    "Control/generalized-alpha/Spectral radius at infinity: " +
                    std::to_string(rho) + " is not between 0 and 1."));
      alpha_m = (2. * rho - 1.) / (rho + 1.);
      alpha_f = rho / (rho + 1.);
      gamma   = 0.5 - alpha_m + alpha_f;
      beta    = 0.25 * (1. - alpha_m + alpha_f) * (1. - alpha_m + alpha_f);
    }



    double
    GeneralizedAlpha::mass_coefficient(const double dt) const
    {
      return (1. - alpha_m) / ((1. - alpha_f) * beta * dt * dt);
    }



    double
    GeneralizedAlpha::first_step_mass_coefficient(const double dt) const
    {
      // With a1 = a0 = 2 (d - dt v0) / dt^2: the same as the others' at
      // rho = 0 and rho = 1.
      return 2. / ((1. - alpha_f) * dt * dt);
    }



    void
    GeneralizedAlpha::add_inertia_terms(const SparseMatrix<double> &mass,
                                        const KinematicState       &start,
                                        const double                dt,
                                        Vector<double>             &rhs) const
    {
      // (alpha_f r0 + M ((1 - alpha_m) / (beta dt) v0
      //  + ((1 - alpha_m) (1/2 - beta) / beta - alpha_m) a0)) / (1 - alpha_f)
      // The first step: M a0 = (1 - alpha_f) r1 + alpha_f r0 with
      // a0 = 2 (d - dt v0) / dt^2 gives the velocity term 2 M v0 / dt.
      Vector<double> mv(start.velocity);
      mv *= start.starting ? 2. / dt : (1. - alpha_m) / (beta * dt);
      if (start.acceleration.size() == mv.size() && !start.starting)
        mv.add((1. - alpha_m) * (0.5 - beta) / beta - alpha_m,
               start.acceleration);
      mv /= 1. - alpha_f;
      mass.vmult_add(rhs, mv);
      rhs.add(alpha_f / (1. - alpha_f), start.inertia_force);
    }



    double
    GeneralizedAlpha::contact_start_weight() const
    {
      return alpha_f;
    }



    bool
    GeneralizedAlpha::needs_initial_acceleration() const
    {
      return true;
    }



    bool
    GeneralizedAlpha::keeps_acceleration() const
    {
      return true;
    }



    void
    GeneralizedAlpha::update(const Vector<double>       &d,
                             const double                dt,
                             const SparseMatrix<double> &mass,
                             const Vector<double>       &contact_correction,
                             KinematicState             &state) const
    {
      Vector<double> &a0 = state.acceleration;
      if (a0.size() != d.size())
        a0.reinit(d.size());
      // The first step's acceleration is constant over the step; a1 below
      // comes out equal to it.
      if (state.starting)
        {
          a0 = d;
          a0.add(-dt, state.velocity);
          a0 *= 2. / (dt * dt);
          state.starting = false;
        }
      // a1 = (d - dt v0 - dt^2 (1/2 - beta) a0) / (beta dt^2)
      Vector<double> a1(d);
      a1.add(-dt, state.velocity, -dt * dt * (0.5 - beta), a0);
      a1 /= beta * dt * dt;
      // r1 = (M ((1 - alpha_m) a1 + alpha_m a0) - alpha_f r0') / (1 - alpha_f),
      // r0' the start force the step used (with the contacts' correction).
      Vector<double> mixed(a1), r1(d.size());
      mixed.sadd(1. - alpha_m, alpha_m, a0);
      mass.vmult(r1, mixed);
      r1.add(-alpha_f, state.inertia_force);
      if (contact_correction.size() == r1.size())
        r1.add(-alpha_f, contact_correction);
      r1 /= 1. - alpha_f;
      state.inertia_force = r1;
      // v1 = v0 + dt ((1 - gamma) a0 + gamma a1)
      state.velocity.add(dt * (1. - gamma), a0, dt * gamma, a1);
      a0 = a1;
    }



    NDDA_REGISTER_PLUGIN(
      TimeIntegrator,
      GeneralizedAlpha,
      "generalized-alpha",
      "Chung and Hulbert's generalized-α method: second order, with the "
      "modes far above 1/dt damped by the factor 'Spectral radius at "
      "infinity' per step (1: Newmark's average acceleration). Meant to be "
      "stable with stiff contacts where Newmark is not (doc/theory.md).")
  } // namespace time
} // namespace ndda
