// SPDX-License-Identifier: GPL-3.0-or-later
//
// How the test programs report the figures doc/validation.md quotes. Kept
// apart from tests.h so that programs which test the geometry alone need not
// include the simulator.
#ifndef ndda_tests_values_h
#define ndda_tests_values_h

#include <chrono>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>

namespace ndda_tests
{
  /**
   * Print a measured figure for doc/validation.md as '@value KEY VALUE';
   * the page's template quotes it as {{KEY}} (scripts/validation_page.py).
   * Keys are 'test name.figure'. @p digits significant digits.
   */
  inline void
  record(const std::string &key, const double value, const int digits = 4)
  {
    std::ostringstream text;
    text << std::setprecision(digits) << value;
    std::cout << "@value " << key << ' ' << text.str() << std::endl;
  }

  /** A count. */
  inline void
  record(const std::string &key, const unsigned int value)
  {
    std::cout << "@value " << key << ' ' << value << std::endl;
  }

  /** A figure that is a text, e.g. 'met' or '**NOT met**'. */
  inline void
  record(const std::string &key, const std::string &text)
  {
    std::cout << "@value " << key << ' ' << text << std::endl;
  }

  /** 'met' or '**NOT met**' for a target. */
  inline std::string
  met(const bool condition)
  {
    return condition ? "met" : "**NOT met**";
  }

  /**
   * Print the wall time since @p start and record it as
   * '@p test.wall_time' (s, two digits; the page quotes it as {{~...}}).
   */
  inline void
  report_wall_time(const std::string                           &test,
                   const std::chrono::steady_clock::time_point &start)
  {
    const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
        .count();
    std::cout << "wall time " << seconds << " s" << std::endl;
    record(test + ".wall_time", seconds, 2);
  }

} // namespace ndda_tests

#endif
