// SPDX-License-Identifier: GPL-3.0-or-later
//
// Small helpers shared by the test programs.
#ifndef ndda_tests_h
#define ndda_tests_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <deal.II/dofs/dof_tools.h>

#include <ndda/parameters/parameters.h>
#include <ndda/simulator.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <string>

namespace ndda_tests
{
  /** Replace every "{key}" in @p text by its value. */
  inline std::string
  substitute(std::string text, const std::map<std::string, std::string> &values)
  {
    for (const auto &[key, value] : values)
      {
        const std::string pattern = "{" + key + "}";
        for (auto pos = text.find(pattern); pos != std::string::npos;
             pos      = text.find(pattern))
          text.replace(pos, pattern.size(), value);
      }
    return text;
  }

  /** Parameters from the text of a .prm file. */
  inline ndda::parameters::Parameters
  read_parameters(const std::string &text, const std::string &name)
  {
    dealii::ParameterHandler     prm;
    ndda::parameters::Parameters parameters;
    parameters.read(text, name + ".prm", prm);
    return parameters;
  }

  /** Fail the test with a message if @p condition is false. */
  inline void
  check(const bool condition, const std::string &what)
  {
    if (!condition)
      {
        std::cout << "FAILED: " << what << std::endl;
        std::exit(1);
      }
  }

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

#ifdef NDDA_TEST_DIR
  /** The text of the example scene prm/NAME.prm. */
  inline std::string
  read_example(const std::string &name)
  {
    std::ifstream file(std::string(NDDA_TEST_DIR) + "/../prm/" + name + ".prm");
    std::stringstream text;
    text << file.rdbuf();
    check(!text.str().empty(), "cannot read prm/" + name + ".prm");
    return text.str();
  }
#endif
} // namespace ndda_tests

#endif
