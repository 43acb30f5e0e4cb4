// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_contact_penalty_coulomb_h
#define ndda_contact_penalty_coulomb_h

#include <ndda/contact/contact_law.h>

namespace ndda
{
  namespace contact
  {
    /**
     * The DDA contact law (thesis 2.3.13, 3.10; doc/contact.md, "Kernels"
     * and "The open-close iteration"), registered as "penalty Coulomb":
     *
     * - a closed (locked or sliding) contact has a normal penalty spring
     *   k_n on its gap g, energy k_n g^2 / 2;
     * - a locked contact also has a shear spring k_s = shear ratio x k_n
     *   to its anchor point, energy k_s s^2 / 2;
     * - a sliding contact carries the Coulomb friction force -sign mu N
     *   along the edge, N = -k_n g the normal force of the same solve;
     * - an open contact closes when it penetrates deeper than the state
     *   tolerance, a closed one opens when its gap exceeds it; a closed
     *   contact is locked while k_s |s| <= mu k_n (-g), else it slides
     *   with sign(s); a sliding contact locks when its motion reverses,
     *   with its shear spring stretched to the friction force it carried.
     *
     * Bonded joints, a separate part of the law: if the joint material
     * has a tensile strength T or a cohesion c (ContactSettings's
     * bond_tension and bond_cohesion, per metre), contacts that touch
     * when the run starts are bonded. A bonded contact stays locked while
     * its normal spring pulls less than T l and its shear spring's force
     * stays within c l + mu N (l its bond length); beyond either limit it
     * breaks for good and goes on as a plain contact (doc/contact.md,
     * "Bonded joints").
     *
     * k_n, the shear ratio, mu and the joint strength come from
     * subsections Contact and Materials, as they did before contact laws
     * were plugins. The law's own entries (`subsection penalty Coulomb`)
     * choose lagged friction: a sliding contact's friction then takes the
     * normal force of the open-close iteration's solve before, as in
     * Shi's DDA, and is a force on the right-hand side alone, so that the
     * matrix stays symmetric; force_lags() makes the iteration solve
     * again until that normal force has settled (doc/contact.md,
     * "Lagged friction").
     *
     * @ingroup contact
     */
    class PenaltyCoulomb : public ContactLaw
    {
    public:
      /** Declares `Lagged friction` and its tolerance. */
      static void
      declare_parameters(ParameterHandler &prm);

      void
      parse_parameters(ParameterHandler &prm) override;

      void
      add_springs(const Option               &o,
                  const ContactState         &contact,
                  const double                scale,
                  const ContactSettings      &settings,
                  dealii::FullMatrix<double> *stiffness,
                  dealii::Vector<double>     &force) const override;

      State
      classify(const Option          &o,
               const ContactState    &contact,
               const Trial           &trial,
               const ContactSettings &settings,
               int                   &sign) const override;

      /**
       * A sliding contact whose motion reverses unloads elastically from
       * the Coulomb limit: its shear spring starts stretched to the
       * friction force it carried, k_s s0 = sign mu k_n (-g). (Anchored
       * unstretched, the friction force would drop to zero at every
       * reversal, and a resting block that vibrates slightly would switch
       * between sliding and locked in every step.) Other contacts lock at
       * o.ratio.
       */
      double
      anchor_on_locking(const Option          &o,
                        const ContactState    &contact,
                        const Trial           &trial,
                        const ContactSettings &settings) const override;

      /** True if the joint has a tensile strength or a cohesion. */
      bool
      bonds_initial_contacts(const ContactSettings &settings) const override;

      /**
       * The normal spring's tension below T l, and the shear spring's
       * force below the Mohr-Coulomb limit c l + mu N (N = -k_n g, so a
       * bond in tension has less shear strength).
       */
      bool
      bond_holds(const Option          &o,
                 const ContactState    &contact,
                 const Trial           &trial,
                 const ContactSettings &settings) const override;

      /** k_n g^2 / 2, plus k_s s^2 / 2 if locked. */
      double
      energy(const Option          &o,
             const ContactState    &contact,
             const Trial           &trial,
             const ContactSettings &settings) const override;

      /** mu times the normal force, weighted over the step as the
       * integrator applies it, times the slip |e_t . d|. */
      double
      friction_dissipation(const Option          &o,
                           const ContactState    &contact,
                           const Trial           &trial,
                           const ContactSettings &settings) const override;

      /**
       * With lagged friction, true for a sliding contact whose normal
       * force (-k_n times the gap, clamped at 0) in the solve of
       * @p trial differs from the one its friction took by more than the
       * tolerance times the larger of the two (plus the state tolerance).
       */
      bool
      force_lags(const Option          &o,
                 const ContactState    &contact,
                 const Trial           &trial,
                 const ContactSettings &settings) const override;

      /** With lagged friction only. */
      bool
      forces_may_lag() const override
      {
        return lagged_friction;
      }

    private:
      /** The gap a sliding contact's lagged friction takes its normal
       * force from: the last solve's, the step's start before the first;
       * clamped at 0 (no friction in tension). */
      double
      friction_gap(const Option &o, const ContactState &contact) const;

      /// Friction from the normal force of the solve before.
      bool lagged_friction = false;
      /// Relative change of that normal force accepted as settled.
      double lag_tolerance = 1e-3;
    };
  } // namespace contact
} // namespace ndda

#endif
