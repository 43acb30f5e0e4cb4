// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_base_expression_h
#define ndda_base_expression_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/point.h>

#include <string>
#include <vector>

namespace ndda
{
  /**
   * A muparser expression of a scene, (x, y) or (x, y, t) with components
   * separated by ';' and the constant pi, together with the entry it comes
   * from. A value that is not finite (a division by zero, sqrt(-1), a
   * history that overflows later in the run) is refused, with a message
   * that names the entry, the component, the point and the time, instead
   * of turning every result of the run into NaN.
   *
   * @ingroup base
   */
  class Expression
  {
  public:
    /**
     * Parse @p expression with @p n_components components; @p entry is the
     * parameter it was given in (e.g. "Loads/push/Force"), for messages.
     */
    Expression(const std::string &expression,
               const unsigned int n_components,
               const bool         time_dependent,
               const std::string &entry);

    /** Set the time of the following evaluations. */
    void
    set_time(const double t);

    /**
     * The value of @p component at @p p; throws an ExcMessage naming the
     * entry if it is not finite.
     */
    double
    value(const dealii::Point<2> &p, const unsigned int component) const;

    /**
     * Evaluate every component at every point of @p points and every time
     * of @p times (value() throws on the first value that is not finite).
     * For --validate: a history that fails only late in the run is found
     * before the run.
     */
    void
    check(const std::vector<dealii::Point<2>> &points,
          const std::vector<double>           &times);

    /** The times check() is meant for: 0 to @p end_time in 64 steps. */
    static std::vector<double>
    check_times(const double end_time);

    /** The parameter entry the expression comes from. */
    const std::string &
    entry() const
    {
      return entry_name;
    }

  private:
    dealii::FunctionParser<2> function;
    std::string               text;
    std::string               entry_name;
    bool                      time_dependent;
  };
} // namespace ndda

#endif
