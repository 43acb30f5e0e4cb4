// SPDX-License-Identifier: GPL-3.0-or-later

#include <deal.II/base/numbers.h>

#include <ndda/base/expression.h>
#include <ndda/base/utilities.h>

#include <cmath>
#include <sstream>

namespace ndda
{
  Expression::Expression(const std::string &expression,
                         const unsigned int n_components,
                         const bool         time_dependent_in,
                         const std::string &entry)
    : function(n_components)
    , text(expression)
    , entry_name(entry)
    , time_dependent(time_dependent_in)
  {
    function.initialize(time_dependent ? "x,y,t" : "x,y",
                        expression,
                        {{"pi", dealii::numbers::PI}},
                        time_dependent);
  }



  void
  Expression::set_time(const double t)
  {
    function.set_time(t);
  }



  double
  Expression::value(const dealii::Point<2> &p,
                    const unsigned int      component) const
  {
    const double v = function.value(p, component);
    if (std::isfinite(v))
      return v;
    std::ostringstream message;
    message << entry_name << ": ";
    if (function.n_components > 1)
      message << "component " << component + 1 << " of ";
    message << "'" << text << "' is "
            << (std::isnan(v) ? "nan" : (v > 0 ? "inf" : "-inf"))
            << " at (x, y) = " << to_string(p);
    if (time_dependent)
      message << ", t = " << function.get_time() << " s";
    message << ". Give an expression that stays finite wherever and "
               "whenever it is used (a division by zero or a function "
               "outside its domain, such as sqrt or log of a negative "
               "number, gives inf or nan; if() can guard it).";
    AssertThrow(false, dealii::ExcMessage(message.str()));
    return v;
  }



  void
  Expression::check(const std::vector<dealii::Point<2>> &points,
                    const std::vector<double>           &times)
  {
    const double start = function.get_time();
    for (const double t : time_dependent ? times : std::vector<double>{0.})
      {
        function.set_time(t);
        for (const auto &p : points)
          for (unsigned int c = 0; c < function.n_components; ++c)
            value(p, c);
      }
    function.set_time(start);
  }



  std::vector<double>
  Expression::check_times(const double end_time)
  {
    const unsigned int  n = 64;
    std::vector<double> times;
    for (unsigned int i = 0; i <= n; ++i)
      times.push_back(end_time * i / n);
    return times;
  }
} // namespace ndda
