// SPDX-License-Identifier: GPL-3.0-or-later
//
// The detection distance of a step: Shi's, or one that follows the motion
// (doc/contact.md, "Detection").

#include <deal.II/base/exceptions.h>

#include <ndda/contact/detection_distance.h>

#include <algorithm>

namespace ndda
{
  namespace contact
  {
    namespace
    {
      /// The last step's largest increment is multiplied by this: twice
      /// for the two sides of a contact, twice for a motion that grows.
      constexpr double motion_factor = 4.;
      /// The distance shrinks by at most this factor a step.
      constexpr double shrink_factor = 0.9;
    } // namespace



    void
    DetectionDistance::initialize(const Rule rule_in, const double full_in)
    {
      AssertThrow(full_in > 0.,
                  dealii::ExcMessage("The contact detection distance must be "
                                     "positive."));
      rule           = rule_in;
      full           = full_in;
      motion         = floor_fraction * full;
      distance       = rule == Rule::scene ? full : motion;
      last_dt        = 0;
      last_increment = 0;
      last_depth     = 0;
      have_step      = false;
      widenings      = 0;
    }



    double
    DetectionDistance::for_step(const double dt)
    {
      if (rule == Rule::scene)
        return distance = full;
      if (!have_step)
        return distance;
      const double growth =
        last_dt > 0. && dt > last_dt ? (dt / last_dt) * (dt / last_dt) : 1.;
      motion   = std::max({motion_factor * last_increment * growth,
                           shrink_factor * motion,
                           floor_fraction * full});
      distance = std::min(full, motion + 2. * last_depth);
      return distance;
    }



    bool
    DetectionDistance::covers(const double max_increment) const
    {
      return distance >= full || 2. * max_increment <= distance;
    }



    double
    DetectionDistance::widen(const double max_increment)
    {
      Assert(!covers(max_increment), dealii::ExcInternalError());
      ++widenings;
      // 2 x max_increment > distance: at least twice the distance.
      motion   = std::min(full, motion_factor * max_increment);
      distance = std::min(full, motion + 2. * last_depth);
      return distance;
    }



    void
    DetectionDistance::accept(const double dt,
                              const double max_increment,
                              const double max_depth)
    {
      last_depth     = max_depth;
      last_dt        = dt;
      last_increment = max_increment;
      have_step      = true;
    }
  } // namespace contact
} // namespace ndda
