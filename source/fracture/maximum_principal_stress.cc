// SPDX-License-Identifier: GPL-3.0-or-later
//
// Maximum principal stress criterion; doc/fracture.md.

#include <ndda/fracture/maximum_principal_stress.h>

#include <cmath>

namespace ndda
{
  namespace fracture
  {
    using namespace dealii;

    double
    largest_principal_stress(const SymmetricTensor<2, 2> &stress)
    {
      const double mean            = 0.5 * (stress[0][0] + stress[1][1]);
      const double half_difference = 0.5 * (stress[0][0] - stress[1][1]);
      return mean + std::hypot(half_difference, stress[0][1]);
    }



    void
    MaximumPrincipalStress::declare_parameters(ParameterHandler &)
    {}



    EdgeFailure
    MaximumPrincipalStress::failure_in_step(const EdgeState &start,
                                            const EdgeState &end,
                                            const Strength  &strength) const
    {
      return earlier_failure(
        limit_crossing_time(
          largest_principal_stress(start.stress) - strength.tensile_strength,
          largest_principal_stress(end.stress) - strength.tensile_strength),
        std::nullopt);
    }



    std::string
    MaximumPrincipalStress::fails_under_any_load(const Strength &strength) const
    {
      if (strength.tensile_strength <= 0.)
        return "Tensile strength is 0: under Fracture/Criterion = Maximum "
               "principal stress every edge with a tensile principal stress "
               "fails at the first instant and the block falls apart in the "
               "first step";
      return "";
    }



    NDDA_REGISTER_FRACTURE_CRITERION(
      MaximumPrincipalStress,
      "Maximum principal stress",
      "An edge fails in tension when the larger principal stress of its "
      "stress tensor exceeds the block material's Tensile strength T "
      "(Rankine). The failure time interpolates the principal stress "
      "linearly within the step. Cohesion and friction angle are not "
      "used.")
  } // namespace fracture
} // namespace ndda
