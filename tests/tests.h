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

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <regex>
#include <sstream>
#include <string>

#include "values.h"

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

  /** @p x with 17 significant digits, for a .prm entry. */
  inline std::string
  exact_number(const double x)
  {
    std::ostringstream out;
    out << std::setprecision(17) << x;
    return out.str();
  }

  /**
   * The point "x, y" at distance @p s along a slope that rises at
   * @p angle (radians) from the origin and @p h above it (normal to it),
   * with 17 digits, for a .prm entry.
   */
  inline std::string
  point_on_slope(const double angle, const double s, const double h)
  {
    return exact_number(s * std::cos(angle) - h * std::sin(angle)) + ", " +
           exact_number(s * std::sin(angle) + h * std::cos(angle));
  }

  /**
   * @p text with every run of white space (deal.II's line breaks and
   * indentation in exception messages) folded into one space, and none at
   * either end.
   */
  inline std::string
  fold_whitespace(const std::string &text)
  {
    std::string folded;
    for (const char c : text)
      if (!std::isspace(static_cast<unsigned char>(c)))
        folded += c;
      else if (!folded.empty() && folded.back() != ' ')
        folded += ' ';
    while (!folded.empty() && folded.back() == ' ')
      folded.pop_back();
    return folded;
  }


  /**
   * The message of the exception that @p action throws, with deal.II's
   * line breaks and indentation folded into single spaces; empty if it
   * throws none.
   */
  template <typename Action>
  std::string
  message_of(const Action &action)
  {
    std::string message;
    try
      {
        action();
      }
    catch (const dealii::ExceptionBase &e)
      {
        std::ostringstream out;
        e.print_info(out);
        message = out.str();
      }
    catch (const std::exception &e)
      {
        message = e.what();
      }
    return fold_whitespace(message);
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

  /**
   * Whether every process of @p comm holds the first process's @p values
   * (a std::vector<double> or a dealii::Vector<double>), to the bit.
   */
  template <class VectorType>
  bool
  same_on_every_process(const VectorType &values, const MPI_Comm comm)
  {
    VectorType first(values);
    dealii::Utilities::MPI::broadcast(&*first.begin(), first.size(), 0, comm);
    return dealii::Utilities::MPI::max(first == values ? 0 : 1, comm) == 0;
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
   * Print a measured value beside the expected one and fail the test if
   * they differ by more than 1e-12 relative to the larger of |expected| and
   * @p scale.
   */
  inline void
  check_value(const std::string &what,
              const double       measured,
              const double       expected,
              const double       scale = 1.)
  {
    std::cout << "  " << what << " = " << std::setprecision(15) << measured
              << " (expected " << expected << ")" << std::endl;
    check(std::abs(measured - expected) <=
            1e-12 * std::max(std::abs(expected), scale),
          what);
  }

  /** Replace the value of "set ENTRY = ..." (the first one) in @p text. */
  inline std::string
  set_entry(const std::string &text,
            const std::string &entry,
            const std::string &value)
  {
    const std::regex line("(set " + entry + " *= *)[^\n]*");
    std::smatch      match;
    check(std::regex_search(text, match, line), "no entry " + entry);
    return match.prefix().str() + match[1].str() + value + match.suffix().str();
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
