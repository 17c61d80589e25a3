#ifndef fgimpact_output_files_h
#define fgimpact_output_files_h

#include <chrono>
#include <cstdint>
#include <fstream>
#include <mpi.h>
#include <string>
#include <utility>
#include <vector>

namespace fgimpact
{
  /// summary.txt's (name, value) pairs in the file's order, the values as
  /// written.
  using SummaryEntries = std::vector<std::pair<std::string, std::string>>;

  /// A PVD file's entries: (time, file name).
  using PvdEntries = std::vector<std::pair<double, std::string>>;

  /**
   * Add an entry to a PVD file's entries in time order, replacing an
   * entry of the same file (the peak force's snapshot, when a higher peak
   * comes); a snapshot between the regular ones falls in its place.
   */
  void
  add_pvd_entry(PvdEntries                           &entries,
                const std::pair<double, std::string> &entry);



  /**
   * A CSV file streamed row by row, with fixed decimals per column so that
   * reference outputs compare cleanly.  Rows are collected and handed to
   * the disk whole, at least every 2 s of wall time, at 1 MiB, and by
   * flush() and the destructor: the file on disk never ends in a torn row.
   * Every write is checked (ExcOutputFailure naming the file).
   */
  class CsvWriter
  {
  public:
    /// columns: name and number of decimals.  resume_length > 0: continue
    /// a file (a resumed run) cut to this many bytes, without a header.
    CsvWriter(const std::string                              &filename,
              const std::vector<std::pair<std::string, int>> &columns,
              const std::uintmax_t resume_length = 0);

    /// Flushes what is left (errors are then ignored: call flush()).
    ~CsvWriter();

    /// Throws ExcMessage unless filename holds at least resume_length bytes
    /// (a file that can be continued from a checkpoint).
    static void
    check_continuable(const std::string   &filename,
                      const std::uintmax_t resume_length);

    void
    write_row(const std::vector<double> &values);

    /// Hand the collected rows to the disk and check the stream.
    void
    flush();

    /// flush() and return the file's length in bytes (for a checkpoint).
    std::uintmax_t
    length();

  private:
    const std::string                     filename;
    std::ofstream                         out;
    std::vector<int>                      decimals;
    std::string                           buffer;
    std::chrono::steady_clock::time_point last_flush;
    std::uintmax_t                        written = 0; // bytes on disk
  };


  /**
   * summary.txt of every problem type: one `name = value` line per result,
   * the unit in the name, fixed decimals (or %.6e) per entry, written at
   * once by write() (to a temporary name, then renamed) so that a failed
   * run leaves no partial summary.  A quantity that does not exist (NaN or
   * Inf, e.g. the contact duration of a ball still in contact at the end
   * time) is written as `none`, never as a number.
   */
  class SummaryWriter
  {
  public:
    /// A value with a fixed number of decimals (0 for counts).
    void
    add(const std::string &name, const double value, const int decimals);

    /// A value in scientific notation with 7 significant digits.
    void
    add_scientific(const std::string &name, const double value);

    /// A word (status = completed).
    void
    add_text(const std::string &name, const std::string &value);

    /// The lines of `other` after these.
    void
    append(const SummaryWriter &other)
    {
      lines.insert(lines.end(), other.lines.begin(), other.lines.end());
    }

    /// Write all lines to filename; throws ExcOutputFailure if it cannot.
    void
    write(const std::string &filename) const;

    /// The (name, value) pairs in the order added, the values as written.
    const SummaryEntries &
    entries() const
    {
      return lines;
    }

    /// Lines written first by every write(), as '#' comments (the run's
    /// provenance; set once by the executable, empty by default).
    static void
    set_preamble(const std::string &comment_lines);

  private:
    static std::string &
    preamble();

    SummaryEntries lines;
  };



  /// Whether a summary value is a number: a finite number by JSON's
  /// grammar (a leading '+' allowed), inf, -inf or nan.
  bool
  is_summary_number(const std::string &value);

  /// summary.json's text: the provenance comments of `preamble` ("# key
  /// value" lines) as the object "provenance", then every entry in order,
  /// a number as a JSON number, none/inf/nan as null, other text as a
  /// string; json.load() and pandas.read_json(typ="series") read it.
  std::string
  summary_json(const std::string &preamble, const SummaryEntries &entries);

  /**
   * study.csv's text: case, the varied entries (`paths`, each case's
   * `values`), every summary key of the cases' `summaries` (the numbers,
   * and the words that say what was modelled and how the case ended; no
   * value holds a comma).  A column whose values are numbers where there
   * are any leaves a case without one (none, or no such key) empty, so
   * that pandas reads it as numbers (NaN there); a word column writes none.
   */
  std::string
  study_csv(const std::vector<std::string>              &paths,
            const std::vector<std::vector<std::string>> &values,
            const std::vector<SummaryEntries>           &summaries);



  /**
   * summary.txt of one run, the one object that writes it: rank 0 writes
   * the file (SummaryWriter: atomically), every rank keeps the entries of
   * the last write, so that a study builds study.csv from memory instead
   * of reading its cases' files back.
   */
  class SummaryFile
  {
  public:
    SummaryFile(const std::string &directory, const MPI_Comm communicator);

    /// Write summary.txt; throws ExcOutputFailure on rank 0 if it cannot.
    void
    write(const SummaryWriter &content);

    /**
     * After a failure: write `content` (its status, failed or interrupted,
     * and what the run knows) unless a summary with that status is written
     * already (the run's own, with its results so far).  Best effort: a
     * failure to write is swallowed, the first failure is the one that
     * counts.
     */
    void
    write_failed(const SummaryWriter &content);

    /// Lines that every later write() adds after its content's (the
    /// thermal step's keys, known before the analysis writes).
    void
    set_appendix(const SummaryWriter &lines)
    {
      appendix = lines;
    }

    /// Keep `content` as the last write's entries without writing (the
    /// ranks that do not write a file their rank 0 wrote: a study reads
    /// its cases' results from memory on every rank).
    void
    keep(const SummaryWriter &content)
    {
      last = content;
      last.append(appendix);
    }

    /// The entries of the last write (none before).
    const SummaryEntries &
    entries() const
    {
      return last.entries();
    }

    /// The value of `status` in the last write ("" if none).
    std::string
    status() const;

  private:
    const std::string filename;
    const bool        root;
    SummaryWriter     last;
    SummaryWriter     appendix;
  };
} // namespace fgimpact

#endif
