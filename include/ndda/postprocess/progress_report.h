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
      struct State
      {
        unsigned int step;
        double       time;
        double       end_time;
        double       step_size;
        unsigned int cuts;
      };

      /** Write the line of @p state at wall time @p wall_time to @p out. */
      void
      print(std::ostream &out, const double wall_time, const State &state);

    private:
      double       interval;
      double       last_wall_time = 0;
      unsigned int last_step      = 0;
    };
  } // namespace postprocess
} // namespace ndda

#endif
