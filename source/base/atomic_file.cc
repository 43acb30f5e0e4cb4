// SPDX-License-Identifier: GPL-3.0-or-later
#include <deal.II/base/exceptions.h>

#include <ndda/base/atomic_file.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <unistd.h>

namespace ndda
{
  AtomicFile::AtomicFile(const std::string &name)
    : name(name)
    , temporary(name + ".tmp")
    , out(temporary, std::ios::trunc)
  {
    AssertThrow(out,
                dealii::ExcMessage("Cannot write " + temporary + " (for " +
                                   name + "): " + std::strerror(errno)));
  }



  AtomicFile::~AtomicFile()
  {
    if (!committed)
      {
        out.close();
        std::remove(temporary.c_str());
      }
  }



  void
  AtomicFile::commit()
  {
    if (out.is_open())
      out.close();
    AssertThrow(!out.fail(),
                dealii::ExcMessage("Writing " + temporary + " (for " + name +
                                   ") failed: is the disk full?"));
    AssertThrow(std::rename(temporary.c_str(), name.c_str()) == 0,
                dealii::ExcMessage("Cannot rename " + temporary + " to " +
                                   name + ": " + std::strerror(errno)));
    committed = true;
  }



  void
  append_to_file(const std::string &name,
                 const std::string &text,
                 const bool         truncate)
  {
    const int fd = ::open(name.c_str(),
                          O_WRONLY | O_CREAT | (truncate ? O_TRUNC : O_APPEND),
                          0644);
    AssertThrow(fd >= 0,
                dealii::ExcMessage("Cannot write " + name + ": " +
                                   std::strerror(errno)));
    std::size_t written = 0;
    while (written < text.size())
      {
        const ssize_t n =
          ::write(fd, text.data() + written, text.size() - written);
        if (n < 0 && errno == EINTR)
          continue;
        if (n <= 0)
          {
            const std::string reason = std::strerror(errno);
            ::close(fd);
            AssertThrow(false,
                        dealii::ExcMessage("Writing " + name +
                                           " failed: " + reason));
          }
        written += n;
      }
    AssertThrow(::close(fd) == 0,
                dealii::ExcMessage("Writing " + name +
                                   " failed: " + std::strerror(errno)));
  }
} // namespace ndda
