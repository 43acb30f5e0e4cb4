// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_postprocess_progress_report_h
#define ndda_postprocess_progress_report_h

#include <ostream>

namespace ndda
{
  namespace postprocess
  {
    /**
     * The progress lines of a run's log: step, time, step size, cuts, the
     * wall time per step since the last line and the time left. The wall
     * time goes here, to the log, and not into the statistics file, so that
     * a statistics file is the same in every run.
     */
    class ProgressReport
    {
    public:
      /** One line every @p interval seconds of wall time. */
      explicit ProgressReport(const double interval = 0)
        : interval(interval)
      {}

      /**
       * Whether a line is due at wall time @p wall_time (s since the
       * start), or @p last (the run's end).
       */
      bool
      due(const double wall_time, const bool last) const
      {
        return last || wall_time - last_wall_time >= interval;
      }

      /** What a line reports. */
      struct Line
      {
        unsigned int step;
        double       time;
        double       end_time;
        double       step_size;
        unsigned int cuts;
      };

      /** Write the line of @p state at wall time @p wall_time to @p out. */
      void
      print(std::ostream &out, const double wall_time, const Line &state);

    private:
      double       interval;
      double       last_wall_time = 0;
      unsigned int last_step      = 0;
    };

    /**
     * When a run writes its frames: at the start, every @p interval
     * seconds of simulated time (every step if zero) and at the end time.
     * Times are compared with a relative tolerance of 1e-12, so that a
     * sum of steps that should land on an output time does.
     */
    class OutputSchedule
    {
    public:
      OutputSchedule(const double interval, const double end_time)
        : interval(interval)
        , end_time(end_time)
        , next(interval)
      {}

      /** Whether the time @p t has reached @p target. */
      static bool
      reached(const double t, const double target)
      {
        return t >= target * (1. - 1e-12);
      }

      /** Whether the run is at its end time at time @p t. */
      bool
      finished(const double t) const
      {
        return reached(t, end_time);
      }

      /**
       * Whether a frame is due at time @p t; if so, the next output time
       * moves past @p t.
       */
      bool
      frame_due(const double t)
      {
        if (!reached(t, next) && !finished(t))
          return false;
        if (interval > 0)
          while (next <= t * (1. + 1e-12))
            next += interval;
        return true;
      }

    private:
      double interval;
      double end_time;
      double next;
    };
  } // namespace postprocess
} // namespace ndda

#endif
