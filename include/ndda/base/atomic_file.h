// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_base_atomic_file_h
#define ndda_base_atomic_file_h

#include <fstream>
#include <string>

namespace ndda
{
  /**
   * An output file that appears complete or not at all: it is written to
   * `<name>.tmp` and renamed to `<name>` by commit() (a rename within a
   * directory is atomic on POSIX file systems). A run killed while it
   * writes leaves the previous version of the file, or none, and a
   * `.tmp` file that the next write replaces. Without commit() (an
   * exception) the temporary file is removed.
   *
   * @ingroup base
   */
  class AtomicFile
  {
  public:
    /** Open `<name>.tmp` for writing; throws naming @p name if it cannot. */
    explicit AtomicFile(const std::string &name);

    /** Remove the temporary file unless commit() was called. */
    ~AtomicFile();

    AtomicFile(const AtomicFile &) = delete;
    AtomicFile &
    operator=(const AtomicFile &) = delete;

    /** The stream to write to. */
    std::ofstream &
    stream()
    {
      return out;
    }

    /** The temporary file's name, for writers that take a file name. */
    const std::string &
    temporary_name() const
    {
      return temporary;
    }

    /** Close, check that everything was written, and rename. */
    void
    commit();

  private:
    std::string   name;
    std::string   temporary;
    std::ofstream out;
    bool          committed = false;
  };

  /**
   * Append @p text to the file @p name with a single write, flushed: a run
   * killed at any moment leaves the file with or without the whole text
   * (rows of the statistics and measure-point files are never cut).
   * @p truncate starts the file anew. Throws naming the file if it cannot.
   */
  void
  append_to_file(const std::string &name,
                 const std::string &text,
                 const bool         truncate = false);
} // namespace ndda

#endif
