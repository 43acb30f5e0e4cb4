// SPDX-License-Identifier: GPL-3.0-or-later

#include <ndda/postprocess/progress_report.h>

#include <algorithm>
#include <iomanip>

namespace ndda
{
  namespace postprocess
  {
    void
    ProgressReport::print(std::ostream &out,
                          const double  wall_time,
                          const Line   &state)
    {
      const double steps_since = state.step - last_step;
      const double per_step =
        (wall_time - last_wall_time) / std::max(steps_since, 1.);
      last_wall_time    = wall_time;
      last_step         = state.step;
      const double rate = state.time / std::max(wall_time, 1e-9);
      out << "  step " << std::setw(7) << state.step
          << "  t = " << std::setw(12) << std::setprecision(6) << state.time
          << " s  dt = " << std::setw(10) << state.step_size << " s"
          << "  cuts " << state.cuts << std::setprecision(3) << "  wall "
          << per_step << " s/step  ETA "
          << std::max(0.,
                      (state.end_time - state.time) / std::max(rate, 1e-300))
          << " s" << std::endl;
    }
  } // namespace postprocess
} // namespace ndda
