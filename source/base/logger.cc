#include <fgimpact/base/exceptions.h>
#include <fgimpact/base/files.h>
#include <fgimpact/base/logger.h>

#include <algorithm>
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



  ProgressMeter::ProgressMeter(const unsigned int n_steps,
                               const bool         enabled,
                               const unsigned int expected_steps)
    : n_steps(n_steps)
    , enabled(enabled && n_steps >= 10)
    , estimated(expected_steps > 0)
    , target(estimated ? std::min(std::max(expected_steps, 10u), n_steps) :
                         n_steps)
  {}



  bool
  ProgressMeter::crossed(const unsigned int step) const
  {
    return next_tenth <= 10 && 10ul * step >= next_tenth * 1ul * target;
  }



  void
  ProgressMeter::update(const unsigned int step, std::ostream &out)
  {
    if (!enabled)
      return;
    // End time = auto past its expected end: half as many steps more.
    if (estimated && step >= target && target < n_steps)
      {
        target     = std::min(n_steps, target + target / 2);
        next_tenth = static_cast<unsigned int>((10ul * step) / target) + 1;
      }
    if (!started)
      {
        // A resumed run starts at its checkpoint: the tenths before it
        // were reported by the earlier process.
        started    = true;
        first_step = step;
        start      = std::chrono::steady_clock::now();
        while (crossed(step))
          ++next_tenth;
        return;
      }
    if (!crossed(step))
      return;
    while (crossed(step))
      ++next_tenth;
    const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
        .count();
    const double eta = elapsed * (target - step) / (step - first_step);
    char         line[160];
    std::snprintf(line,
                  sizeof(line),
                  "  progress %3u %%  step %u of %s%u  elapsed %.1f s  ETA "
                  "%.1f s\n",
                  static_cast<unsigned int>((100ul * step) / target),
                  step,
                  estimated ? "about " : "",
                  target,
                  elapsed,
                  eta);
    out << line;
  }
} // namespace fgimpact
