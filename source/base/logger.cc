#include <fgimpact/base/exceptions.h>
#include <fgimpact/base/files.h>
#include <fgimpact/base/logger.h>

#include <cstdio>
#include <cstring>
#include <iostream>

namespace fgimpact
{
  void
  Logger::Sink::write(const char *text, const std::streamsize n)
  {
    if (file.is_open())
      file.write(text, n);
    else
      pending.append(text, n);
  }



  void
  Logger::Sink::check()
  {
    if (!file.is_open() || file.good())
      return;
    file.close();
    const std::string warning = "fgimpact: warning: cannot write " + filename +
                                " (disk full or I/O error); the log goes on "
                                "on the screen only\n";
    if (screen != nullptr)
      screen->sputn(warning.data(), warning.size());
  }



  Logger::TeeBuffer::TeeBuffer(std::streambuf *original, Sink &sink)
    : original(original)
    , sink(sink)
  {}



  Logger::TeeBuffer::int_type
  Logger::TeeBuffer::overflow(int_type c)
  {
    if (traits_type::eq_int_type(c, traits_type::eof()))
      return traits_type::not_eof(c);
    const char ch = traits_type::to_char_type(c);
    xsputn(&ch, 1);
    return c;
  }



  std::streamsize
  Logger::TeeBuffer::xsputn(const char *s, std::streamsize n)
  {
    // The screen is best effort (a closed pipe, SIGPIPE ignored): the
    // stream must not turn bad, or log.txt would stop too.
    original->sputn(s, n);
    sink.write(s, n);
    if (std::memchr(s, '\n', n) != nullptr)
      sync();
    return n;
  }



  int
  Logger::TeeBuffer::sync()
  {
    if (sink.file.is_open())
      {
        sink.file.flush();
        sink.check();
      }
    original->pubsync(); // best effort, as in xsputn()
    return 0;
  }



  Logger::Logger(const bool active)
    : active(active)
  {
    if (!active)
      return;
    // printf-style output of the libraries as well: line by line.
    std::setvbuf(stdout, nullptr, _IOLBF, BUFSIZ);
    sink.screen = std::cerr.rdbuf();
    out         = std::make_unique<TeeBuffer>(std::cout.rdbuf(), sink);
    err         = std::make_unique<TeeBuffer>(std::cerr.rdbuf(), sink);
    std::cout.rdbuf(out.get());
    std::cerr.rdbuf(err.get());
  }



  Logger::~Logger()
  {
    if (!active)
      return;
    std::cout.flush();
    std::cerr.flush();
    std::cout.rdbuf(out->original);
    std::cerr.rdbuf(err->original);
  }



  void
  Logger::open(const std::string &filename,
               const std::string &header,
               const bool         append)
  {
    if (!active)
      return;
    // append: a resumed run continues the log of the run it continues.
    // A log.txt that cannot be written at the start is a start file that
    // cannot be written (exit code 2); later, a warning (Sink::check()).
    sink.filename = filename;
    if (!append) // a resumed log is already the run's
      record_output_file(filename);
    sink.file.open(filename, append ? std::ios::app : std::ios::out);
    sink.file << header << sink.pending << std::flush;
    sink.pending.clear();
    if (!sink.file)
      {
        sink.file.close();
        AssertThrow(false,
                    ExcOutputFailure("cannot write " + filename +
                                     " (disk full or I/O error)."));
      }
  }



  ProgressMeter::ProgressMeter(const unsigned int n_steps, const bool enabled)
    : n_steps(n_steps)
    , enabled(enabled && n_steps >= 10)
  {}



  void
  ProgressMeter::update(const unsigned int step, std::ostream &out)
  {
    if (!enabled)
      return;
    const auto crossed = [&]() {
      return next_tenth <= 10 && 10ul * step >= next_tenth * 1ul * n_steps;
    };
    if (!started)
      {
        // A resumed run starts at its checkpoint: the tenths before it
        // were reported by the earlier process.
        started    = true;
        first_step = step;
        start      = std::chrono::steady_clock::now();
        while (crossed())
          ++next_tenth;
        return;
      }
    if (!crossed())
      return;
    while (crossed())
      ++next_tenth;
    const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
        .count();
    const double eta = elapsed * (n_steps - step) / (step - first_step);
    char         line[160];
    std::snprintf(line,
                  sizeof(line),
                  "  progress %3u %%  step %u of %u  elapsed %.1f s  ETA "
                  "%.1f s\n",
                  static_cast<unsigned int>((100ul * step) / n_steps),
                  step,
                  n_steps,
                  elapsed,
                  eta);
    out << line;
  }
} // namespace fgimpact
