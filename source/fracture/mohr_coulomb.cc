// SPDX-License-Identifier: GPL-3.0-or-later
//
// Mohr-Coulomb with a tension cut-off, thesis 5.24-5.34 as corrected in
// doc/fracture.md.

#include <ndda/fracture/mohr_coulomb.h>

#include <cmath>

namespace ndda
{
  namespace fracture
  {
    using namespace dealii;

    MohrCoulomb::MohrCoulomb(const bool tension_cut_off)
      : tension_cut_off(tension_cut_off)
    {}



    void
    MohrCoulomb::declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("Tension cut-off",
                        "true",
                        Patterns::Bool(),
                        "Whether an edge also fails in tension when its "
                        "normal stress exceeds the material's tensile "
                        "strength (the thesis's criterion, figure 5.3). "
                        "Without it only the Coulomb line decides.");
    }



    void
    MohrCoulomb::parse_parameters(ParameterHandler &prm)
    {
      tension_cut_off = prm.get_bool("Tension cut-off");
    }



    EdgeFailure
    MohrCoulomb::failure_in_step(const EdgeState &start,
                                 const EdgeState &end,
                                 const Strength  &strength) const
    {
      std::optional<double> tension_time;
      if (tension_cut_off)
        tension_time =
          limit_crossing_time(start.normal_stress - strength.tensile_strength,
                              end.normal_stress - strength.tensile_strength);

      // Excess of the shear stress over the shear strength on the branch
      // where the shear stress has the sign s: s tau + sigma_n tan(phi) - c
      // (thesis 5.33's f with tau -> s tau, sigma -> -sigma_n).
      const double tan_phi = std::tan(strength.friction_angle);
      const auto   excess  = [&](const EdgeState &state, const double s) {
        return s * state.shear_stress + state.normal_stress * tan_phi -
               strength.cohesion;
      };
      std::optional<double> shear_time;
      for (const double s : {1., -1.})
        if (const auto t =
              limit_crossing_time(excess(start, s), excess(end, s));
            t && (!shear_time || *t < *shear_time))
          shear_time = t;

      return earlier_failure(tension_time, shear_time);
    }



    std::string
    MohrCoulomb::fails_under_any_load(const Strength &strength) const
    {
      // With c = 0 the Coulomb excess |tau| + sigma_n tan(phi) is
      // homogeneous in the stress: an edge that fails at all within a step
      // fails at its start. Only a pure pressure on every edge (a
      // hydrostatic state) escapes.
      if (strength.cohesion <= 0.)
        return "Cohesion is 0: under Fracture/Criterion = Mohr-Coulomb an "
               "edge without cohesion fails in shear under any shear "
               "stress, so every loaded edge fails at the first instant and "
               "the block falls apart into its cells in the first step";
      if (tension_cut_off && strength.tensile_strength <= 0.)
        return "Tensile strength is 0: with Fracture/Mohr-Coulomb/Tension "
               "cut-off = true every edge in tension fails at the first "
               "instant and the block falls apart in the first step";
      return "";
    }



    NDDA_REGISTER_FRACTURE_CRITERION(
      MohrCoulomb,
      "Mohr-Coulomb",
      "The thesis's criterion (chapter 5): an edge fails in tension when "
      "its normal stress exceeds the tensile strength T, and in shear when "
      "the magnitude of its shear stress exceeds c - sigma_n tan(phi) "
      "(sigma_n tension positive); c, phi and T are the block material's "
      "Cohesion, Friction angle and Tensile strength. Failure times are "
      "found by linear interpolation within the step; the earlier mode "
      "wins.")
  } // namespace fracture
} // namespace ndda
