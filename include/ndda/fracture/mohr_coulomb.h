// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_fracture_mohr_coulomb_h
#define ndda_fracture_mohr_coulomb_h

#include <ndda/fracture/fracture_criterion.h>

namespace ndda
{
  namespace fracture
  {
    /**
     * The Mohr-Coulomb criterion with a tension cut-off on the edge (thesis
     * 5.1, figure 5.3, 5.24-5.34), registered as "Mohr-Coulomb". With
     * sigma_n the normal stress on the edge (tension positive) and tau the
     * shear stress, both linear in time within the step:
     *
     * - tension: the edge fails when sigma_n > T;
     * - shear: the edge fails when |tau| > c - sigma_n tan(phi), i.e. when
     *   max(+tau, -tau) + sigma_n tan(phi) - c > 0. Each of the two
     *   branches is linear in time, so the shear failure time is the
     *   earlier of their two linear crossing times; this is exact for the
     *   linearly varying stresses even when tau changes sign within the
     *   step.
     *
     * An edge beyond a limit at the start of the step fails at time 0. The
     * earlier mode wins, tension on a tie. doc/fracture.md derives this and
     * lists where it departs from the thesis's formulas.
     *
     * Parameters (subsection Fracture/Mohr-Coulomb): `Tension cut-off`.
     *
     * @ingroup fracture
     */
    class MohrCoulomb : public FractureCriterion
    {
    public:
      /**
       * @param tension_cut_off Whether the edge also fails in tension when
       *   sigma_n exceeds T (the thesis's criterion); without it, only the
       *   Coulomb line decides, which in tension reaches zero shear strength
       *   at sigma_n = c / tan(phi).
       */
      explicit MohrCoulomb(const bool tension_cut_off = true);

      /** Declare `Tension cut-off`. */
      static void
      declare_parameters(ParameterHandler &prm);

      void
      parse_parameters(ParameterHandler &prm) override;

      EdgeFailure
      failure_in_step(const EdgeState &start,
                      const EdgeState &end,
                      const Strength  &strength) const override;

      std::string
      fails_under_any_load(const Strength &strength) const override;

    private:
      bool tension_cut_off;
    };
  } // namespace fracture
} // namespace ndda

#endif
