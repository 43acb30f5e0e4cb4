// SPDX-License-Identifier: GPL-3.0-or-later

#include <ndda/base/log_file.h>

namespace ndda
{
  namespace
  {
    /** A stream buffer that writes to two buffers (console and log). */
    class TeeBuffer : public std::streambuf
    {
    public:
      TeeBuffer(std::streambuf *a, std::streambuf *b)
        : a(a)
        , b(b)
      {}

    protected:
      int
      overflow(int c) override
      {
        if (c == EOF)
          return !EOF;
        const int ra = a->sputc(c), rb = b->sputc(c);
        return (ra == EOF || rb == EOF) ? EOF : c;
      }
      int
      sync() override
      {
        return (a->pubsync() == 0 && b->pubsync() == 0) ? 0 : -1;
      }

    private:
      std::streambuf *a, *b;
    };
  } // namespace



  LogFile::~LogFile()
  {
    close();
  }



  void
  LogFile::open(const std::string &file_name,
                std::ostream      &console,
                const bool         append)
  {
    close();
    file.open(file_name, append ? std::ios::app : std::ios::trunc);
    this->console   = &console;
    original_buffer = console.rdbuf();
    tee = std::make_unique<TeeBuffer>(original_buffer, file.rdbuf());
    console.rdbuf(tee.get());
  }



  void
  LogFile::close()
  {
    if (console == nullptr)
      return;
    console->flush();
    console->rdbuf(original_buffer);
    console = nullptr;
    tee.reset();
    file.close();
  }
} // namespace ndda
