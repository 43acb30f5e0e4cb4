// SPDX-License-Identifier: GPL-3.0-or-later
#include <deal.II/base/exceptions.h>

#include <ndda/base/atomic_file.h>
#include <ndda/postprocess/statistics_table.h>

#include <cstdio>
#include <sstream>

namespace ndda
{
  namespace postprocess
  {
    void
    StatisticsTable::start_row()
    {
      ++n_started;
      for (auto &c : columns)
        c.values.resize(n_started - n_written, 0.);
      last_column = 0;
    }



    StatisticsTable::Column &
    StatisticsTable::column(const std::string &name, const bool integer)
    {
      // The column just used (set_scientific() after add_value()), or the
      // one after it.
      for (unsigned int i = (last_column > 0 ? last_column - 1 : 0);
           i < columns.size() && i <= last_column;
           ++i)
        if (columns[i].name == name)
          {
            last_column = i + 1;
            return columns[i];
          }
      for (unsigned int i = 0; i < columns.size(); ++i)
        if (columns[i].name == name)
          {
            last_column = i + 1;
            return columns[i];
          }
      AssertThrow(n_written == 0,
                  dealii::ExcMessage(
                    "Statistics column '" + name +
                    "' appeared after rows had been written to " + file +
                    ": a postprocessor must add its columns from the first "
                    "time step on."));
      Column c;
      c.name    = name;
      c.integer = integer;
      c.values.resize(n_started, 0.);
      columns.push_back(std::move(c));
      last_column = columns.size();
      return columns.back();
    }



    void
    StatisticsTable::add(const std::string &name,
                         const double       value,
                         const bool         integer)
    {
      AssertThrow(n_started > n_written,
                  dealii::ExcMessage("StatisticsTable: add_value('" + name +
                                     "') before start_row()."));
      column(name, integer).values.back() = value;
    }



    void
    StatisticsTable::set_scientific(const std::string &name,
                                    const bool         scientific)
    {
      column(name, false).scientific = scientific;
    }



    void
    StatisticsTable::set_precision(const std::string &name,
                                   const unsigned int precision)
    {
      column(name, false).precision = precision;
    }



    std::vector<std::string>
    StatisticsTable::column_names() const
    {
      std::vector<std::string> names;
      for (const auto &c : columns)
        names.push_back(c.name);
      return names;
    }



    void
    StatisticsTable::write_header(std::ostream &out) const
    {
      for (unsigned int i = 0; i < columns.size(); ++i)
        out << "# " << i + 1 << ": " << columns[i].name << '\n';
    }



    void
    StatisticsTable::write_rows(std::ostream &out) const
    {
      const unsigned int n_held = n_started - n_written;
      char               buffer[64];
      std::string        line;
      for (unsigned int r = 0; r < n_held; ++r)
        {
          line.clear();
          for (const auto &c : columns)
            {
              const double v = r < c.values.size() ? c.values[r] : 0.;
              int          n = 0;
              if (c.integer)
                n = std::snprintf(buffer,
                                  sizeof(buffer),
                                  "%lld",
                                  static_cast<long long>(v));
              else
                n = std::snprintf(buffer,
                                  sizeof(buffer),
                                  c.scientific ? "%.*e" : "%.*f",
                                  static_cast<int>(c.precision),
                                  v);
              if (!line.empty())
                line += ' ';
              line.append(buffer, n);
            }
          line += '\n';
          out << line;
        }
    }



    void
    StatisticsTable::write_text(std::ostream &out) const
    {
      write_header(out);
      write_rows(out);
    }



    void
    StatisticsTable::write(const std::string &file_name)
    {
      const bool first = file.empty();
      AssertThrow(first || file == file_name,
                  dealii::ExcMessage("StatisticsTable: rows were written to " +
                                     file + ", not to " + file_name));
      // One write of all the rows: a run killed at any moment leaves whole
      // rows.
      std::ostringstream text;
      if (first)
        write_header(text);
      write_rows(text);
      append_to_file(file_name, text.str(), first);
      file = file_name;
      // write() is called between steps: every row is complete.
      n_written = n_started;
      for (auto &c : columns)
        c.values.clear();
    }
  } // namespace postprocess
} // namespace ndda
