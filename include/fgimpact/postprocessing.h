#ifndef fgimpact_postprocessing_h
#define fgimpact_postprocessing_h

#include <deal.II/base/data_out_base.h>

#include <deal.II/lac/trilinos_vector.h>

#include <deal.II/numerics/data_postprocessor.h>

#include <fgimpact/plate_model.h>

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
   * time series file up to date after every write so that a run stopped
   * early still opens in ParaView.
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

    /// Wait for the pending snapshot, rethrowing its errors.
    void
    finish();

  private:
    const PlateModel                           &plate;
    const std::string                           directory;
    StressPostprocessor                         postprocessor;
    TrilinosWrappers::MPI::Vector               u_ghosted, v_ghosted;
    std::vector<std::pair<double, std::string>> times_and_names;
    std::future<void>                           pending;

    const DataOutBase::VtkFlags::ZlibCompressionLevel compression;
  };



  /**
   * A CSV file streamed row by row (nothing kept in memory), with fixed
   * decimals per column so that reference outputs compare cleanly.
   */
  class CsvWriter
  {
  public:
    /// columns: name and number of decimals.
    CsvWriter(const std::string                              &filename,
              const std::vector<std::pair<std::string, int>> &columns);

    void
    write_row(const std::vector<double> &values);

  private:
    std::ofstream    out;
    std::vector<int> decimals;
  };


  /**
   * summary.txt of every problem type: one `name = value` line per result,
   * the unit in the name, fixed decimals (or %.6e) per entry, written at
   * once by write() so that a failed run leaves no partial summary.
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

    /// Write all lines to filename; throws ExcMessage if it cannot.
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
