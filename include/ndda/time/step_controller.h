// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_time_step_controller_h
#define ndda_time_step_controller_h

#include <string>

namespace ndda
{
  namespace time
  {
    /** How one attempt at a time step ended. */
    enum class AttemptResult
    {
      accepted,
      /// The largest displacement exceeded the allowed ratio.
      too_large,
      /// The open-close iteration did not settle.
      not_settled,
      /// Automatic penalty: raised; solve the step again.
      penalty_raised,
      /// A cell would turn inside out.
      inverted,
      /// The attempt moved further than its contacts were detected for:
      /// detect them again and solve the step again at the same size.
      detect_again
    };

    /**
     * The step size of every attempt at a time step, and the limits that
     * stop a run which cannot go on (DDA step control, thesis 2.3.13 and
     * 3.11; ASPECT's time stepping manager plays the same part there):
     *
     * - an attempt starts at the nominal step, or at what is left to the
     *   end time, or at twice the last accepted step after a cut; where
     *   that growth fails again, the size is held for 1, 2, 4, ... up to
     *   32 accepted steps before the next try (until a growth holds);
     * - a failed attempt is cut to half its size, up to a limit of cuts in
     *   one step; a raised contact penalty retries the same size, up to 30
     *   raises;
     * - a run whose step falls below 1e-6 of the nominal step, or whose
     *   last 1000 steps were all below 1e-3 of it, crawls: it is stopped.
     *
     * Every stop throws an ExcMessage that names the step, the time, the
     * limit and the entries that change it.
     *
     * @ingroup time
     */
    class StepController
    {
    public:
      /** The limits, from subsections Control and Contact. */
      struct Limits
      {
        /// Control/Time step (s).
        double nominal_step = 0;
        /// Control/End time (s).
        double end_time = 0;
        /// Control/Maximum step cuts.
        unsigned int max_cuts = 0;
        /// Control/Maximum displacement ratio (for messages).
        double max_displacement_ratio = 0;
        /// Contact/Open-close iterations (for messages).
        unsigned int max_open_close_iterations = 0;
      };

      StepController() = default;

      explicit StepController(const Limits &limits);

      /**
       * A new step, the @p step-th (counting from 1), starts at time @p t:
       * its counters start at zero.
       */
      void
      begin_step(const unsigned int step, const double t);

      /**
       * The size of a first attempt from time @p t: the present step size,
       * or what is left to the end time. A remainder within round-off of
       * the step size keeps the step size (and the factorization).
       */
      double
      attempt_size(const double t) const;

      /**
       * An attempt of size @p dt ended with @p result (not accepted);
       * @p max_increment is its largest displacement increment (m), for
       * messages. Returns the size of the next attempt; throws when a
       * limit is reached.
       */
      double
      after_failure(const AttemptResult result,
                    const double        dt,
                    const double        max_increment);

      /**
       * The step was accepted with size @p dt: the next step starts at
       * twice that, at most the nominal step, or at @p dt while a failed
       * growth holds it (see the class's description).
       */
      void
      accept(const double dt);

      /**
       * After the step's statistics are recorded: throws if the run
       * crawls (1000 steps in a row below 1e-3 of the nominal step).
       * @p time is the time at the step's end.
       */
      void
      check_progress(const double time);

      /** Cuts in the present step (all attempts, all crack events). */
      unsigned int
      n_cuts() const
      {
        return cuts;
      }

      /** Of those, cuts because the open-close iteration did not settle. */
      unsigned int
      n_open_close_cuts() const
      {
        return open_close_cuts;
      }

      /** Cuts since the start of the run. */
      unsigned int
      n_total_cuts() const
      {
        return total_cuts;
      }

      /** Size of the last accepted step (s). */
      double
      last_step_size() const
      {
        return last_dt;
      }

      /** Write the controller's state (not its limits, which come from
       * the `.prm`) to a checkpoint or read it (Archive). */
      template <class Archive>
      void
      serialize(Archive &ar)
      {
        ar &step_size &last_dt &step &start_time &cuts &open_close_cuts &raises
          &total_cuts &crawling_steps &hold &held &growing;
      }

    private:
      /** "Step N at t = T: " for messages. */
      std::string
      where() const;

      Limits       limits;
      double       step_size       = 0;
      double       last_dt         = 0;
      unsigned int step            = 0;
      double       start_time      = 0;
      unsigned int cuts            = 0;
      unsigned int open_close_cuts = 0;
      unsigned int raises          = 0;
      unsigned int total_cuts      = 0;
      unsigned int crawling_steps  = 0;
      /// Accepted steps to hold a size after a cut before growing (0: at
      /// once), those held so far, and whether the present step size is
      /// a growth that has not yet held.
      unsigned int hold    = 0;
      unsigned int held    = 0;
      bool         growing = false;
    };
  } // namespace time
} // namespace ndda

#endif
