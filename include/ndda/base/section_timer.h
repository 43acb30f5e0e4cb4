// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_base_section_timer_h
#define ndda_base_section_timer_h

#include <chrono>
#include <ostream>
#include <string>
#include <vector>

namespace ndda
{
  /**
   * Wall time spent in named sections of a run, and a table of them at
   * the end, as deal.II's TimerOutput with TimerOutput::wall_times prints
   * it.
   *
   * TimerOutput also reads the process's CPU time at every section (a
   * getrusage() system call, a few microseconds on a virtual machine)
   * and finds the section by a std::string key: in a scene of a few
   * blocks that was a quarter of a time step. This timer reads the
   * monotonic clock only, and finds a section by comparing its name with
   * the few sections already seen.
   *
   * @ingroup base
   */
  class SectionTimer
  {
  public:
    using Clock = std::chrono::steady_clock;

    /** Time spent in @p section from construction to destruction. */
    class Scope
    {
    public:
      Scope(SectionTimer &timer, const char *section);
      ~Scope();
      Scope(const Scope &) = delete;
      Scope &
      operator=(const Scope &) = delete;

    private:
      SectionTimer     &timer;
      unsigned int      index;
      Clock::time_point start;
    };

    SectionTimer();

    /** The table of sections (calls, wall time, share of the total). */
    void
    print_summary(std::ostream &out) const;

    /** The wall time spent in @p section so far (zero if never entered). */
    double
    section_time(const std::string &section) const;

  private:
    struct Section
    {
      std::string  name;
      unsigned int calls   = 0;
      double       seconds = 0;
    };

    /** The index of @p name, added if new. */
    unsigned int
    find(const char *name);

    Clock::time_point    created;
    std::vector<Section> sections;
  };



  /** Seconds since construction or the last restart(), by the monotonic
   * clock (deal.II's Timer also reads the CPU time). */
  class WallClock
  {
  public:
    WallClock()
      : start(std::chrono::steady_clock::now())
    {}

    void
    restart()
    {
      start = std::chrono::steady_clock::now();
    }

    double
    seconds() const
    {
      return std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                           start)
        .count();
    }

  private:
    std::chrono::steady_clock::time_point start;
  };
} // namespace ndda

#endif
