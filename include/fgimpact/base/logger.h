#ifndef fgimpact_logger_h
#define fgimpact_logger_h

#include <chrono>
#include <fstream>
#include <memory>
#include <ostream>
#include <streambuf>
#include <string>

namespace fgimpact
{
  /**
   * The executable's log: while it lives, everything written to std::cout
   * and std::cerr is flushed line by line (so that a redirected stdout
   * shows the run as it goes, and a killed run keeps its log) and copied
   * into log.txt once open() names it; what was printed before open() is
   * kept and written first.  Only rank 0 logs; on other ranks it does
   * nothing.
   */
  class Logger
  {
  public:
    explicit Logger(const bool active);

    /// Restores std::cout and std::cerr.
    ~Logger();

    /// Start log.txt: `header` first, then everything printed so far.
    void
    open(const std::string &filename,
         const std::string &header,
         const bool         append = false);

  private:
    /// Where both streams' copies go: a file once open, a string before.
    struct Sink
    {
      std::ofstream   file;
      std::string     pending;
      std::string     filename;
      std::streambuf *screen = nullptr; // the original stderr

      void
      write(const char *text, const std::streamsize n);

      /// A write to the open file that failed (disk full): one warning on
      /// the screen, and the file closed; the log goes on on the screen.
      void
      check();
    };

    /// Writes to the original buffer and the sink, flushing at newlines.
    class TeeBuffer : public std::streambuf
    {
    public:
      TeeBuffer(std::streambuf *original, Sink &sink);

      std::streambuf *const original;

    protected:
      int_type
      overflow(int_type c) override;
      std::streamsize
      xsputn(const char *s, std::streamsize n) override;
      int
      sync() override;

    private:
      Sink &sink;
    };

    const bool                 active;
    Sink                       sink;
    std::unique_ptr<TeeBuffer> out, err;
  };



  /**
   * Progress lines every tenth of the time steps: the step, the elapsed
   * wall time since the first step and the estimated time to the end.  They
   * hold wall-clock times, so the monitor prints them only with
   * Output/Print timing = true (the reproducible logs of the tests switch
   * it off).
   *
   * With End time = auto the last step is not known: the tenths and the
   * ETA count to an expected number of steps ("step 40 of about 160"), which
   * grows by half, up to the Maximum end time's, each time the run reaches
   * it and goes on.
   */
  class ProgressMeter
  {
  public:
    /// n_steps: the run's steps, or with expected_steps > 0 (End time =
    /// auto) the most it may take.
    ProgressMeter(const unsigned int n_steps,
                  const bool         enabled,
                  const unsigned int expected_steps = 0);

    /// Call after every step; the first call (step 0, or the checkpoint's
    /// step on --resume) starts the clock.  Prints when step crosses the
    /// next tenth: the time elapsed in this process and the time left at
    /// this process's rate.
    void
    update(const unsigned int step, std::ostream &out);

  private:
    /// Whether step has reached the next tenth of the target.
    bool
    crossed(const unsigned int step) const;

    const unsigned int                    n_steps;
    const bool                            enabled;
    const bool                            estimated; // End time = auto
    unsigned int                          target;    // steps counted to
    bool                                  started    = false;
    unsigned int                          first_step = 0;
    unsigned int                          next_tenth = 1;
    std::chrono::steady_clock::time_point start;
  };
} // namespace fgimpact

#endif
