// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_base_log_file_h
#define ndda_base_log_file_h

#include <fstream>
#include <memory>
#include <ostream>
#include <streambuf>
#include <string>

namespace ndda
{
  /**
   * A copy of a console stream in a file: after open(), everything
   * written to the stream also goes to the file, until close() (or the
   * destructor) gives the stream its own buffer back.
   *
   * @ingroup base
   */
  class LogFile
  {
  public:
    ~LogFile();

    /** Copy @p console into the file @p file_name from now on (after
     * what it holds, with @p append). */
    void
    open(const std::string &file_name,
         std::ostream      &console,
         const bool         append = false);

    /** Flush, and write @p console to its own buffer again. */
    void
    close();

  private:
    std::ofstream                   file;
    std::unique_ptr<std::streambuf> tee;
    std::ostream                   *console         = nullptr;
    std::streambuf                 *original_buffer = nullptr;
  };
} // namespace ndda

#endif
