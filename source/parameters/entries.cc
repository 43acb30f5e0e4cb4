// SPDX-License-Identifier: GPL-3.0-or-later

#include <deal.II/base/function_parser.h>
#include <deal.II/base/utilities.h>

#include <ndda/parameters/entries.h>

#include <cmath>
#include <set>
#include <sstream>

namespace ndda
{
  namespace parameters
  {
    using namespace dealii;

    /** The text of ParameterHandler's exception, without the stack. */
    std::string
    message_of(const ExceptionBase &exc, const std::string &filename)
    {
      std::ostringstream out;
      exc.print_info(out);
      std::string text = out.str();
      // ParameterHandler reads from a string here: "Line <3> of file
      // <input string>: ..." becomes "line 3: ...".
      if (!filename.empty())
        for (const auto &[from, to] :
             std::vector<std::pair<std::string, std::string>>{
               {"> of file <input string>", ""},
               {"> of file <input string", ":"},
               {"Line <", "line "},
               {":: ", ": "}})
          for (auto pos = text.find(from); pos != std::string::npos;
               pos      = text.find(from))
            text.replace(pos, from.size(), to);
      // Collapse deal.II's line breaks and indentation.
      std::string result;
      bool        space = false;
      for (const char c : text)
        if (c == '\n' || c == ' ' || c == '\t')
          space = true;
        else
          {
            if (space && !result.empty())
              result += ' ';
            result += c;
            space = false;
          }
      return result;
    }



    /** Split at @p delimiter and trim; empty pieces are dropped. */
    std::vector<std::string>
    split(const std::string &text, const std::string &delimiter)
    {
      std::vector<std::string> pieces;
      for (const auto &piece : Utilities::split_string_list(text, delimiter))
        if (!piece.empty())
          pieces.push_back(piece);
      return pieces;
    }



    double
    to_double(const std::string &text, const std::string &entry)
    {
      std::istringstream in(text);
      double             value;
      in >> value;
      AssertThrow(in && (in >> std::ws).eof() && std::isfinite(value),
                  ExcMessage(entry + ": '" + text +
                             "' is not a number. Give plain numbers such as "
                             "0.5 or 1e-3."));
      return value;
    }



    std::vector<double>
    parse_numbers(const std::string &text,
                  const std::string &entry,
                  const unsigned int n)
    {
      std::vector<double> numbers;
      for (const auto &piece : split(text, ","))
        numbers.push_back(to_double(piece, entry));
      AssertThrow(numbers.size() == n,
                  ExcMessage(entry + ": '" + text + "' has " +
                             std::to_string(numbers.size()) + " numbers, but " +
                             std::to_string(n) +
                             " separated by commas are needed."));
      return numbers;
    }



    /** Names in a comma separated list, checked to be unique. */
    std::vector<std::string>
    parse_names(const std::string &text, const std::string &entry)
    {
      const auto            names = split(text, ",");
      std::set<std::string> seen;
      for (const auto &name : names)
        AssertThrow(seen.insert(name).second,
                    ExcMessage(entry + ": the name '" + name +
                               "' appears twice. Names must be unique."));
      return names;
    }



    std::string
    angle_description(const std::string &what)
    {
      return what + " (degrees).";
    }



    std::vector<std::vector<Point<2>>>
    parse_rings(const std::string &text, const std::string &entry)
    {
      std::vector<std::vector<Point<2>>> rings;
      for (const auto &ring : split(text, "|"))
        rings.push_back(parse_points(ring, entry));
      return rings;
    }



    std::vector<Point<2>>
    parse_points(const std::string &text, const std::string &entry)
    {
      std::vector<Point<2>> points;
      for (const auto &piece : split(text, ";"))
        {
          const auto xy = parse_numbers(piece, entry, 2);
          points.emplace_back(xy[0], xy[1]);
        }
      return points;
    }



    std::vector<geometry::Segment>
    parse_segments(const std::string &text, const std::string &entry)
    {
      std::vector<geometry::Segment> segments;
      for (const auto &piece : split(text, ";"))
        {
          const auto c = parse_numbers(piece, entry, 4);
          segments.push_back({Point<2>(c[0], c[1]), Point<2>(c[2], c[3])});
          AssertThrow(segments.back().a.distance(segments.back().b) > 0.,
                      ExcMessage(entry + ": the segment '" + piece +
                                 "' has zero length. Give two different end "
                                 "points x1, y1, x2, y2."));
        }
      return segments;
    }



    void
    check_function(const std::string &expression,
                   const unsigned int n_components,
                   const std::string &variables,
                   const std::string &entry)
    {
      const auto components = Utilities::split_string_list(expression, ";");
      AssertThrow(components.size() == n_components,
                  ExcMessage(entry + ": '" + expression + "' has " +
                             std::to_string(components.size()) +
                             " components separated by ';', but " +
                             std::to_string(n_components) +
                             " are needed (variables: " + variables + ")."));
      // muparser parses a component, and reports its unknown variables,
      // only when it is evaluated: evaluate each.
      unsigned int component = 0;
      const auto   invalid   = [&](const std::string &reason) {
        AssertThrow(false,
                    ExcMessage(
                      entry + ": " +
                      (n_components > 1 ?
                             "component " + std::to_string(component + 1) + " ('" +
                           Utilities::trim(components[component]) + "') of " :
                             std::string()) +
                      "'" + expression + "' is not a valid function of (" +
                      variables + "): " + reason));
      };
      try
        {
          FunctionParser<2> function(n_components);
          function.initialize(variables,
                              expression,
                              {{"pi", numbers::PI}},
                              variables.find('t') != std::string::npos);
          for (; component < n_components; ++component)
            function.value(Point<2>(), component);
        }
      catch (const ExceptionBase &exc)
        {
          invalid(message_of(exc));
        }
      catch (const std::exception &exc)
        {
          invalid(exc.what());
        }
    }
  } // namespace parameters
} // namespace ndda
