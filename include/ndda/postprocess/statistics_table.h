// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_postprocess_statistics_table_h
#define ndda_postprocess_statistics_table_h

#include <ostream>
#include <string>
#include <type_traits>
#include <vector>

namespace ndda
{
  namespace postprocess
  {
    /**
     * The statistics file: one row per time step, one column per figure,
     * written as deal.II's TableHandler writes
     * `simple_table_with_separate_column_description` tables (a line
     * `# N: name` per column, then the rows, separated by spaces).
     *
     * TableHandler formats every value into a string when it is added and
     * keeps the whole table: in a scene of a few blocks that was a third
     * of a time step, and a long run rewrote an ever longer file at every
     * progress line. This table keeps the numbers of the rows not yet
     * written, formats them when they are written, and appends them to the
     * file.
     *
     * Columns are made by their first value, in that order. A row that
     * leaves a column out writes 0 there. All columns must exist when the
     * first rows are written: a column that appears later is an error.
     *
     * @ingroup postprocess
     */
    class StatisticsTable
    {
    public:
      /** Begin the row of a new time step. */
      void
      start_row();

      /** @p value in column @p column of the present row; an integer
       * column is written without decimals. */
      template <typename Number>
      void
      add_value(const std::string &column, const Number value)
      {
        static_assert(std::is_arithmetic_v<Number>,
                      "statistics columns hold numbers");
        add(column, static_cast<double>(value), std::is_integral_v<Number>);
      }

      /** Write column @p column in scientific notation (or not). */
      void
      set_scientific(const std::string &column, const bool scientific);

      /** Write column @p column with @p precision digits after the point
       * (default 4). */
      void
      set_precision(const std::string &column, const unsigned int precision);

      /** The rows started so far. */
      unsigned int
      n_rows() const
      {
        return n_started;
      }

      /** The column names, in order. */
      std::vector<std::string>
      column_names() const;

      /**
       * Write the rows not written yet to file @p file_name: the whole
       * file (header and rows) the first time, appended after that. The
       * written rows are then forgotten.
       */
      void
      write(const std::string &file_name);

      /** The header and the rows not yet written, to @p out. */
      void
      write_text(std::ostream &out) const;

      /**
       * Write the table's columns and count of rows to a checkpoint, or
       * read them (Archive); the file is @p file_name now (the output
       * directory may have another name when the run resumes).
       */
      template <class Archive>
      void
      serialize(Archive &ar, const std::string &file_name)
      {
        bool                                            written = !file.empty();
        ar &columns &last_column &n_started &n_written &written;
        if (ar.loading())
          file = written ? file_name : "";
      }

    private:
      struct Column
      {
        std::string         name;
        bool                integer    = false;
        bool                scientific = false;
        unsigned int        precision  = 4;
        std::vector<double> values;

        template <class Archive>
        void
        serialize(Archive &ar)
        {
          ar &name &integer &scientific &precision &values;
        }
      };

      void
      add(const std::string &column, const double value, const bool integer);

      /** The column @p name, made if new (an @p integer column). */
      Column &
      column(const std::string &name, const bool integer);

      void
      write_header(std::ostream &out) const;

      void
      write_rows(std::ostream &out) const;

      std::vector<Column> columns;
      /// One past the column used last: column() looks there first
      /// (columns come in the same order every row).
      unsigned int last_column = 0;
      unsigned int n_started   = 0;
      /// Rows already in the file (and no longer held).
      unsigned int n_written = 0;
      /// The file written to (empty before the first write).
      std::string file;
    };
  } // namespace postprocess
} // namespace ndda

#endif
