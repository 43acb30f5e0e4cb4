// SPDX-License-Identifier: GPL-3.0-or-later

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <ndda/time/step_controller.h>

#include <algorithm>

namespace ndda
{
  namespace time
  {
    using dealii::ExcMessage;
    using dealii::Utilities::to_string;

    namespace
    {
      /// Raises of the automatic penalty in one step at most.
      constexpr unsigned int max_penalty_raises = 30;
      /// Below this fraction of the nominal step a cut step stops the run.
      constexpr double smallest_step = 1e-6;
      /// Steps below this fraction of the nominal step crawl...
      constexpr double crawling_step = 1e-3;
      /// ... and this many of them in a row stop the run.
      constexpr unsigned int max_crawling_steps = 1000;
      /// Most accepted steps a size is held after a failed growth.
      constexpr unsigned int max_hold = 32;
    } // namespace



    StepController::StepController(const Limits &limits)
      : limits(limits)
      , step_size(limits.nominal_step)
    {}



    std::string
    StepController::where() const
    {
      return "Step " + std::to_string(step) +
             " at t = " + to_string(start_time) + ": ";
    }



    void
    StepController::begin_step(const unsigned int step_in, const double t)
    {
      step            = step_in;
      start_time      = t;
      cuts            = 0;
      open_close_cuts = 0;
      raises          = 0;
    }



    double
    StepController::attempt_size(const double t) const
    {
      const double remaining = limits.end_time - t;
      return remaining < step_size * (1. - 1e-9) ? remaining : step_size;
    }



    double
    StepController::after_failure(const AttemptResult result,
                                  const double        dt,
                                  const double        max_increment)
    {
      Assert(result != AttemptResult::detect_again, dealii::ExcInternalError());
      if (result == AttemptResult::penalty_raised)
        {
          ++raises;
          AssertThrow(raises <= max_penalty_raises,
                      ExcMessage(where() +
                                 "the automatic penalty was doubled 30 "
                                 "times and the penetration still exceeds "
                                 "Contact/Maximum penetration ratio. "
                                 "Increase the ratio or reduce the time "
                                 "step."));
          return dt;
        }
      ++cuts;
      if (result == AttemptResult::not_settled)
        ++open_close_cuts;
      const std::string reason =
        result == AttemptResult::not_settled ?
          "the open-close iteration still changes contact states after "
          "Contact/Open-close iterations = " +
            std::to_string(limits.max_open_close_iterations) + " solves" :
        result == AttemptResult::inverted ?
          std::string("a cell still turns inside out (the motion diverges "
                      "or the step is far too large)") :
          "the largest displacement increment " + to_string(max_increment) +
            " m still exceeds Control/Maximum displacement ratio " +
            to_string(limits.max_displacement_ratio) +
            " of half the scene height";
      AssertThrow(cuts <= limits.max_cuts,
                  ExcMessage(where() + reason + ", after " +
                             std::to_string(cuts - 1) +
                             " step cuts. Increase 'Maximum step cuts' or "
                             "the limit named, or reduce the time step."));
      const double next = 0.5 * dt;
      // Steps that each need a cut shrink the step without bound when the
      // motion diverges: stop rather than crawl.
      // An open-close iteration that needs more solves than allowed
      // fails at every size as well: the message names which it is.
      AssertThrow(
        next >= smallest_step * limits.nominal_step,
        ExcMessage(
          where() +
          "the step size fell below 1e-6 of Control/Time step after cuts "
          "in step after step" +
          (result == AttemptResult::not_settled ?
             ": " + reason + " at every size tried (largest increment " +
               to_string(max_increment) +
               " m). Smaller steps do not help a scene whose contact "
               "states take more solves to settle (many contacts, "
               "loads passed on from course to course): raise "
               "Contact/Open-close iterations." :
             "; the motion is diverging (" + reason + ").") +
          " Look at the last output and the statistics file; see "
          "doc/contact.md, 'Known limits'."));
      return next;
    }



    void
    StepController::accept(const double dt)
    {
      total_cuts += cuts;
      last_dt = dt;
      // After a cut, grow back towards the nominal step: at once, unless
      // growing has just failed. Every grown attempt that fails again
      // doubles the steps the size is held before the next try (at most
      // max_hold); one that holds lets the next cut grow at once again.
      // A scene that needs a smaller step for a while then pays a failed
      // attempt every max_hold steps rather than one in every step.
      if (growing)
        hold = cuts > 0 ? std::min(std::max(2 * hold, 1u), max_hold) : 0;
      held      = cuts > 0 ? 0 : held + 1;
      step_size = held >= hold ? std::min(2. * dt, limits.nominal_step) : dt;
      growing   = step_size > dt;
      crawling_steps =
        dt < crawling_step * limits.nominal_step ? crawling_steps + 1 : 0;
    }



    void
    StepController::check_progress(const double time)
    {
      // Each step starts at twice the last step size, so a motion that
      // needs a cut in step after step can crawl on at a small step size
      // without ever falling below the limit of after_failure(). Stop once
      // 1000 steps in a row were below 1e-3 of the nominal step (all of
      // them together cover less than one nominal step).
      AssertThrow(crawling_steps < max_crawling_steps,
                  ExcMessage(
                    "Step " + std::to_string(step) +
                    " at t = " + to_string(time) +
                    ": 1000 steps in a row were cut below 1e-3 of "
                    "Control/Time step (the last one " +
                    to_string(last_dt) +
                    " s); the run crawls. The motion is diverging or the "
                    "contacts chatter: look at the last output and the "
                    "statistics file; see doc/contact.md, 'Known limits'."));
    }
  } // namespace time
} // namespace ndda
