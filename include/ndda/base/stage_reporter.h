// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_base_stage_reporter_h
#define ndda_base_stage_reporter_h

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <ostream>
#include <string>
#include <thread>

namespace ndda
{
  /**
   * Word from a long setup: the stages of a setup (meshing, numbering the
   * unknowns, ...) are announced only when one of them takes longer than
   * a few seconds, so that a large scene does not sit silent and a small
   * one prints nothing.
   *
   * A watcher thread wakes when the present stage has run for
   * @p quiet_seconds and prints "  <prefix><stage> ...", then a line every
   * @p repeat_seconds while the stage goes on; a stage that was announced
   * prints its time when it ends. The lines go to @p out, written only by
   * the watcher while a stage runs and by the caller between stages (the
   * two never write at once: both hold the lock). begin() on a running
   * stage does not wake the watcher, so that a stage a time step costs
   * a lock and no context switch.
   *
   * @ingroup base
   */
  class StageReporter
  {
  public:
    explicit StageReporter(std::ostream      &out,
                           const double       quiet_seconds  = 5.,
                           const double       repeat_seconds = 30.,
                           const std::string &prefix         = "setup: ");

    /** Ends the last stage and stops the watcher. */
    ~StageReporter();

    StageReporter(const StageReporter &) = delete;
    StageReporter &
    operator=(const StageReporter &) = delete;

    /** End the present stage (if any) and begin stage @p name. */
    void
    begin(const std::string &name);

    /** End the present stage. */
    void
    end();

  private:
    using Clock = std::chrono::steady_clock;

    void
    watch();

    /** End the present stage; the lock is held. */
    void
    end_locked();

    std::ostream           &out;
    const std::string       prefix;
    const Clock::duration   quiet;
    const Clock::duration   repeat;
    std::mutex              mutex;
    std::condition_variable wake;
    std::string             stage;
    Clock::time_point       started;
    /// When the stage was last announced (started: not yet).
    Clock::time_point announced;
    bool              running = false;
    bool              stop    = false;
    std::thread       watcher;
  };
} // namespace ndda

#endif
