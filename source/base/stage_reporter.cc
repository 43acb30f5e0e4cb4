// SPDX-License-Identifier: GPL-3.0-or-later
#include <ndda/base/stage_reporter.h>

#include <exception>
#include <iomanip>

namespace ndda
{
  namespace
  {
    double
    seconds(const std::chrono::steady_clock::duration d)
    {
      return std::chrono::duration<double>(d).count();
    }
  } // namespace



  StageReporter::StageReporter(std::ostream      &out,
                               const double       quiet_seconds,
                               const double       repeat_seconds,
                               const std::string &prefix)
    : out(out)
    , prefix(prefix)
    , quiet(std::chrono::duration_cast<Clock::duration>(
        std::chrono::duration<double>(quiet_seconds)))
    , repeat(std::chrono::duration_cast<Clock::duration>(
        std::chrono::duration<double>(repeat_seconds)))
    , watcher([this]() { watch(); })
  {}



  StageReporter::~StageReporter()
  {
    {
      std::lock_guard<std::mutex> lock(mutex);
      // A stage left by an exception did not finish.
      if (std::uncaught_exceptions() == 0)
        end_locked();
      stop = true;
    }
    wake.notify_all();
    watcher.join();
  }



  void
  StageReporter::begin(const std::string &name)
  {
    bool idle = false;
    {
      std::lock_guard<std::mutex> lock(mutex);
      idle = !running || announced != started;
      end_locked();
      stage     = name;
      started   = Clock::now();
      announced = started;
      running   = true;
    }
    // A watcher that waits for the last stage's due time wakes then and
    // finds the new one later.
    if (idle)
      wake.notify_all();
  }



  void
  StageReporter::end()
  {
    std::lock_guard<std::mutex> lock(mutex);
    end_locked();
  }



  void
  StageReporter::end_locked()
  {
    if (running && announced != started)
      out << "  " << prefix << stage << " done in " << std::setprecision(3)
          << seconds(Clock::now() - started) << " s" << std::endl;
    running = false;
  }



  void
  StageReporter::watch()
  {
    std::unique_lock<std::mutex> lock(mutex);
    while (!stop)
      {
        if (!running)
          {
            wake.wait(lock);
            continue;
          }
        const auto due =
          announced == started ? started + quiet : announced + repeat;
        if (Clock::now() < due)
          {
            wake.wait_until(lock, due);
            continue;
          }
        out << "  " << prefix << stage;
        if (announced == started)
          out << " ..." << std::endl;
        else
          out << ", " << std::setprecision(3) << seconds(Clock::now() - started)
              << " s so far" << std::endl;
        announced = Clock::now();
      }
  }
} // namespace ndda
