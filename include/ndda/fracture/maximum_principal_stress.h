// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_fracture_maximum_principal_stress_h
#define ndda_fracture_maximum_principal_stress_h

#include <ndda/fracture/fracture_criterion.h>

namespace ndda
{
  namespace fracture
  {
    /**
     * The maximum principal stress criterion (Rankine; thesis 8.2 names it
     * as an alternative to Mohr-Coulomb), registered as "Maximum principal
     * stress". An edge fails in tension when the larger principal stress
     * sigma_1 of its stress tensor (EdgeState::stress, tension positive)
     * exceeds the tensile strength T. The failure time interpolates sigma_1
     * linearly between the start and the end of the step; an edge beyond T
     * at the start fails at time 0.
     *
     * If the stress tensor itself varies linearly in time, sigma_1(t) is
     * convex in t, so the linear interpolation never misses a failure
     * within the step and gives a time no later than the exact one (they
     * agree unless the principal directions turn within the step; see
     * doc/fracture.md). The criterion looks at the edge's stress only, not
     * at its orientation; cohesion and friction angle are not used.
     *
     * No parameters of its own.
     *
     * @ingroup fracture
     */
    class MaximumPrincipalStress : public FractureCriterion
    {
    public:
      /** Declares nothing. */
      static void
      declare_parameters(ParameterHandler &prm);

      EdgeFailure
      failure_in_step(const EdgeState &start,
                      const EdgeState &end,
                      const Strength  &strength) const override;

      std::string
      fails_under_any_load(const Strength &strength) const override;
    };

    /**
     * The larger principal stress of a 2D stress tensor,
     * (s_xx + s_yy)/2 + sqrt(((s_xx - s_yy)/2)^2 + s_xy^2).
     */
    double
    largest_principal_stress(const SymmetricTensor<2, 2> &stress);
  } // namespace fracture
} // namespace ndda

#endif
