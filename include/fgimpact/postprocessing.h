#ifndef fgimpact_postprocessing_h
#define fgimpact_postprocessing_h

#include <deal.II/base/data_out_base.h>

#include <deal.II/lac/trilinos_vector.h>

#include <deal.II/numerics/data_postprocessor.h>

#include <fgimpact/plate_model.h>

#include <chrono>
#include <fstream>
#include <future>
#include <string>
#include <utility>
#include <vector>

namespace fgimpact
{
  using namespace dealii;

  /**
   * Stress tensor (MPa), von Mises stress (MPa), E (GPa) and rho (kg/m^3)
   * from the displacement, for DataOut.  E and the stress come from the
   * same PropertyInterpolator and HookeLaw as the assembly and the probes.
   */
  class StressPostprocessor : public DataPostprocessor<3>
  {
  public:
    explicit StressPostprocessor(const PlateModel &plate);

    void
    evaluate_vector_field(
      const DataPostprocessorInputs::Vector<3> &inputs,
      std::vector<Vector<double>> &computed_quantities) const override;

    std::vector<std::string>
    get_names() const override;

    std::vector<DataComponentInterpretation::DataComponentInterpretation>
    get_data_component_interpretation() const override;

    UpdateFlags
    get_needed_update_flags() const override;

  private:
    const PropertyInterpolator properties;
    const HookeLaw             hooke;
  };



  /**
   * Writes VTU files (one piece per MPI rank plus a .pvtu record) of the
   * displacement, velocity, stresses and material fields, and keeps the PVD
   * time series file up to date so that a run stopped early still opens in
   * ParaView: the PVD (written to a temporary name and renamed) lists a
   * snapshot only once its files are complete.  A failed write throws
   * ExcOutputFailure naming the file.
   */
  class VtuWriter
  {
  public:
    VtuWriter(const PlateModel                                 &plate,
              const std::string                                &directory,
              const DataOutBase::VtkFlags::ZlibCompressionLevel compression =
                DataOutBase::VtkFlags::best_speed);

    /// Waits for the last snapshot to be written.
    ~VtuWriter();

    /**
     * Write one snapshot at time t (s); u, v in m and m/s.  The vectors
     * are copied and the patches are built and written in a background
     * task, off the time loop's critical path; the next call (or the
     * destructor) waits for it.
     */
    void
    write(const unsigned int                   step,
          const double                         t,
          const TrilinosWrappers::MPI::Vector &u,
          const TrilinosWrappers::MPI::Vector &v);

    /// Wait for the pending snapshot, rethrowing its errors, and list it
    /// in the PVD.
    void
    finish();

  private:
    const PlateModel                           &plate;
    const std::string                           directory;
    StressPostprocessor                         postprocessor;
    TrilinosWrappers::MPI::Vector               u_ghosted, v_ghosted;
    std::vector<std::pair<double, std::string>> times_and_names;
    std::pair<double, std::string>              pending_record;
    bool                                        record_pending = false;
    std::future<void>                           pending;

    const DataOutBase::VtkFlags::ZlibCompressionLevel compression;
  };



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
    /// columns: name and number of decimals.
    CsvWriter(const std::string                              &filename,
              const std::vector<std::pair<std::string, int>> &columns);

    /// Flushes what is left (errors are then ignored: call flush()).
    ~CsvWriter();

    void
    write_row(const std::vector<double> &values);

    /// Hand the collected rows to the disk and check the stream.
    void
    flush();

  private:
    const std::string                     filename;
    std::ofstream                         out;
    std::vector<int>                      decimals;
    std::string                           buffer;
    std::chrono::steady_clock::time_point last_flush;
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

    /// Write all lines to filename; throws ExcOutputFailure if it cannot.
    void
    write(const std::string &filename) const;

    /// Lines written first by every write(), as '#' comments (the run's
    /// provenance; set once by the executable, empty by default).
    static void
    set_preamble(const std::string &comment_lines);

  private:
    static std::string &
    preamble();

    std::string text;
  };
} // namespace fgimpact

#endif
