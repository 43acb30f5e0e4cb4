// SPDX-License-Identifier: GPL-3.0-or-later
//
// The DDA contact law: penalty normal spring, shear spring, Coulomb
// friction (doc/contact.md, "Kernels"), and bonded joints.

#include <ndda/contact/penalty_coulomb.h>

#include <algorithm>
#include <cmath>

namespace ndda
{
  namespace contact
  {
    void
    PenaltyCoulomb::declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry(
        "Lagged friction",
        "false",
        dealii::Patterns::Bool(),
        "false: a sliding contact's friction force takes the normal force "
        "of the same solve, which puts a non-symmetric term into the "
        "matrix (friction makes `direct` take an LU factorization, and "
        "CG-Jacobi BiCGStab). true: it takes the normal force of the "
        "open-close iteration's solve before (in the first solve of a step, "
        "of the step's start), as Shi's DDA does, and goes to the "
        "right-hand side alone, so that the matrix stays symmetric "
        "(Cholesky, CG); while a sliding contact's normal force moved by "
        "more than the Lagged friction tolerance, the iteration solves "
        "again in the same states before it classifies the contacts (at "
        "most Open-close iterations such solves in a step). Slower on the "
        "ringing wall of doc/performance.md ('Lagged friction'): more "
        "solves a step.");
      prm.declare_entry(
        "Lagged friction tolerance",
        "1e-3",
        dealii::Patterns::Double(0.),
        "With Lagged friction: the largest change of a sliding contact's "
        "normal force between two solves, relative to the force, at which "
        "the normal forces count as settled and the contacts are "
        "classified.");
    }



    void
    PenaltyCoulomb::parse_parameters(ParameterHandler &prm)
    {
      lagged_friction = prm.get_bool("Lagged friction");
      lag_tolerance   = prm.get_double("Lagged friction tolerance");
    }



    double
    PenaltyCoulomb::friction_gap(const Option       &o,
                                 const ContactState &contact) const
    {
      return std::min(std::isnan(contact.solved_gap) ? o.gap :
                                                       contact.solved_gap,
                      0.);
    }



    bool
    PenaltyCoulomb::force_lags(const Option          &o,
                               const ContactState    &contact,
                               const Trial           &trial,
                               const ContactSettings &settings) const
    {
      if (!lagged_friction || contact.state != State::sliding ||
          contact.sign == 0 || contact.friction <= 0.)
        return false;
      const double used = friction_gap(o, contact);
      const double now  = std::min(trial.gap, 0.);
      return std::abs(now - used) >
             lag_tolerance * std::max(-now, -used) + settings.state_tolerance;
    }



    void
    PenaltyCoulomb::add_springs(const Option               &o,
                                const ContactState         &contact,
                                const double                scale,
                                const ContactSettings      &settings,
                                dealii::FullMatrix<double> *stiffness,
                                dealii::Vector<double>     &force) const
    {
      const double       kn = scale * settings.normal_stiffness;
      const double       ks = settings.shear_ratio * kn;
      const unsigned int n  = o.dofs.size();
      // Normal spring: energy kn/2 (g0 + e_n.d)^2.
      for (unsigned int i = 0; i < n; ++i)
        {
          force[o.dofs[i]] -= kn * o.gap * o.wn[i];
          if (stiffness != nullptr)
            for (unsigned int j = 0; j < n; ++j)
              (*stiffness)(i, j) += kn * o.wn[i] * o.wn[j];
        }
      if (contact.state == State::locked)
        {
          // Shear spring to the anchor: energy ks/2 (s0 + e_t.d)^2.
          const double s0 = (o.ratio - contact.anchor) * o.length;
          for (unsigned int i = 0; i < n; ++i)
            {
              force[o.dofs[i]] -= ks * s0 * o.wt[i];
              if (stiffness != nullptr)
                for (unsigned int j = 0; j < n; ++j)
                  (*stiffness)(i, j) += ks * o.wt[i] * o.wt[j];
            }
        }
      else if (contact.sign != 0 && contact.friction > 0. && lagged_friction)
        {
          // Coulomb friction -sign mu N along the tangent, with the normal
          // force N = -kn g of the solve before (force_lags()): a force
          // alone, the matrix stays symmetric.
          const double f =
            contact.sign * contact.friction * kn * friction_gap(o, contact);
          for (unsigned int i = 0; i < n; ++i)
            force[o.dofs[i]] += f * o.wt[i];
        }
      else if (contact.sign != 0 && contact.friction > 0.)
        {
          // Coulomb friction -sign mu N along the tangent, with the normal
          // force N = -kn (g0 + e_n.d) of the same solve: the force vector
          // sign mu kn (g0 + e_n.d) e_t, whose d-dependent part goes to the
          // (non-symmetric) matrix.
          const double f = contact.sign * contact.friction * kn;
          for (unsigned int i = 0; i < n; ++i)
            {
              force[o.dofs[i]] += f * o.gap * o.wt[i];
              if (stiffness != nullptr)
                for (unsigned int j = 0; j < n; ++j)
                  (*stiffness)(i, j) -= f * o.wt[i] * o.wn[j];
            }
        }
    }



    State
    PenaltyCoulomb::classify(const Option          &o,
                             const ContactState    &contact,
                             const Trial           &trial,
                             const ContactSettings &settings,
                             int                   &sign) const
    {
      const double g = trial.gap;
      const bool   was_closed =
        contact.state == State::locked || contact.state == State::sliding;
      sign = 0;
      // A band of +-tolerance around contact keeps contacts that carry no
      // force (faces that just touch) from flipping between solves.
      if (g > settings.state_tolerance ||
          (!was_closed && g >= -settings.state_tolerance))
        return State::open;
      if (g > 0.)
        {
          sign = contact.sign; // touching without force: keep the state
          return contact.state;
        }

      const double kn    = settings.normal_stiffness;
      const double limit = contact.friction * kn * std::max(-g, 0.);
      if (limit <= 0.)
        return State::sliding; // frictionless: never locked
      if (contact.state == State::sliding && contact.sign != 0)
        {
          // Keeps sliding until the relative motion reverses.
          if (contact.sign * trial.increment >= -settings.state_tolerance)
            {
              sign = contact.sign;
              return State::sliding;
            }
          return State::locked;
        }
      // Open or locked (or sliding without a direction yet): the shear
      // spring against the Coulomb limit.
      const double s = o.shear_displacement(contact.anchor, trial.increment);
      if (settings.shear_ratio * kn * std::abs(s) > limit)
        {
          sign = s > 0. ? 1 : -1;
          return State::sliding;
        }
      return State::locked;
    }



    double
    PenaltyCoulomb::anchor_on_locking(const Option          &o,
                                      const ContactState    &contact,
                                      const Trial           &trial,
                                      const ContactSettings &settings) const
    {
      double anchor = o.ratio;
      if (contact.state == State::sliding && contact.sign != 0)
        anchor -= contact.sign * contact.friction * std::max(-trial.gap, 0.) /
                  (settings.shear_ratio * o.length);
      return anchor;
    }



    double
    PenaltyCoulomb::energy(const Option          &o,
                           const ContactState    &contact,
                           const Trial           &trial,
                           const ContactSettings &settings) const
    {
      const double kn     = settings.normal_stiffness;
      double       energy = 0.5 * kn * trial.gap * trial.gap;
      if (contact.state == State::locked)
        {
          const double ks = settings.shear_ratio * kn;
          const double s =
            o.shear_displacement(contact.anchor, trial.increment);
          energy += 0.5 * ks * s * s;
        }
      return energy;
    }



    double
    PenaltyCoulomb::friction_dissipation(const Option          &o,
                                         const ContactState    &contact,
                                         const Trial           &trial,
                                         const ContactSettings &settings) const
    {
      if (contact.state != State::sliding || contact.sign == 0 ||
          contact.friction <= 0.)
        return 0.;
      // The friction force -sign mu N e_t acts with the weights of the
      // integrator's contact forces: the start gap's normal force weighted
      // start_weight, the end gap's the rest. It does the work
      // -sign mu N (e_t . d); its negative is what friction takes out.
      const double w = settings.start_weight;
      const double normal_force =
        settings.normal_stiffness *
        (w * std::max(-o.gap, 0.) + (1. - w) * std::max(-trial.gap, 0.));
      return contact.sign * contact.friction * normal_force * trial.increment;
    }



    // Bonded joints.

    bool
    PenaltyCoulomb::bonds_initial_contacts(
      const ContactSettings &settings) const
    {
      return settings.bond_tension > 0. || settings.bond_cohesion > 0.;
    }



    bool
    PenaltyCoulomb::bond_holds(const Option          &o,
                               const ContactState    &contact,
                               const Trial           &trial,
                               const ContactSettings &settings) const
    {
      const double kn      = settings.normal_stiffness;
      const double g       = trial.gap;
      const double tension = kn * g; // positive: the spring pulls
      if (g > settings.state_tolerance &&
          tension > settings.bond_tension * contact.bond_length)
        return false;
      const double s = o.shear_displacement(contact.anchor, trial.increment);
      const double limit = settings.bond_cohesion * contact.bond_length -
                           contact.friction * tension;
      return settings.shear_ratio * kn * std::abs(s) <= std::max(limit, 0.);
    }



    NDDA_REGISTER_CONTACT_LAW(
      PenaltyCoulomb,
      "penalty Coulomb",
      "The DDA contact law (thesis 3.10, doc/contact.md): a closed contact "
      "has a normal penalty spring (Contact/Penalty factor); a locked one "
      "also a shear spring (Contact/Shear stiffness ratio) to its anchor "
      "point; a sliding one carries Coulomb friction, mu = tan of the "
      "joint friction angle (Materials). A closed contact slides when its "
      "shear spring's force exceeds mu times the normal force, and locks "
      "again when its motion reverses. Bonded joints: if Materials/Joint "
      "has a tensile strength or a cohesion, contacts that touch when the "
      "run starts stay locked until the normal spring pulls harder than "
      "the tensile strength or the shear spring exceeds cohesion plus "
      "friction (Mohr-Coulomb, per metre of joint), and then go on as "
      "plain contacts (doc/contact.md, 'Bonded joints'). Its own entries "
      "choose where friction takes its normal force from: the same solve "
      "(a non-symmetric matrix) or the solve before (Lagged friction, a "
      "symmetric one).")
  } // namespace contact
} // namespace ndda
