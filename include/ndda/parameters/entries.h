// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_parameters_entries_h
#define ndda_parameters_entries_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/point.h>

#include <ndda/geometry/block_mesh.h>

#include <string>
#include <vector>

namespace ndda
{
  /**
   * Reading entries of a `.prm` file: lists, numbers, points, segments and
   * functions, each checked, with messages that name the entry. Every
   * layer's parameters use them.
   *
   * @ingroup parameters
   */
  namespace parameters
  {
    using dealii::Point;

    /**
     * The text of the exception @p exc (ParameterHandler's), without the
     * stack, on one line; with @p filename, "Line <3> of file <input
     * string>" becomes "line 3".
     */
    std::string
    message_of(const dealii::ExceptionBase &exc,
               const std::string           &filename = "");

    /** Split at @p delimiter and trim; empty pieces are dropped. */
    std::vector<std::string>
    split(const std::string &text, const std::string &delimiter);

    /** The number @p text; throws naming @p entry if it is none. */
    double
    to_double(const std::string &text, const std::string &entry);

    /** Exactly @p n numbers separated by commas. */
    std::vector<double>
    parse_numbers(const std::string &text,
                  const std::string &entry,
                  const unsigned int n);

    /** Names in a comma separated list, checked to be unique. */
    std::vector<std::string>
    parse_names(const std::string &text, const std::string &entry);

    /** The documentation of an angle entry: "@p what (degrees).". */
    std::string
    angle_description(const std::string &what);

    /** Rings of points separated by '|'. */
    std::vector<std::vector<Point<2>>>
    parse_rings(const std::string &text, const std::string &entry);

    /**
     * Parse "x, y; x, y; ..." into points. @p entry names the entry in the
     * error message.
     */
    std::vector<Point<2>>
    parse_points(const std::string &text, const std::string &entry);

    /** Parse "x1, y1, x2, y2; ..." into segments. */
    std::vector<geometry::Segment>
    parse_segments(const std::string &text, const std::string &entry);

    /**
     * Check that @p expression is a valid muparser expression with
     * @p n_components components separated by ';' in the given variables;
     * throws naming @p entry otherwise.
     */
    void
    check_function(const std::string &expression,
                   const unsigned int n_components,
                   const std::string &variables,
                   const std::string &entry);
  } // namespace parameters
} // namespace ndda

#endif
