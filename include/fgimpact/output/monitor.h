#ifndef fgimpact_monitor_h
#define fgimpact_monitor_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/timer.h>

#include <fgimpact/app/logger.h>
#include <fgimpact/contact/contact_model.h>
#include <fgimpact/output/checkpoint.h>
#include <fgimpact/output/contact_output.h>
#include <fgimpact/output/output_files.h>
#include <fgimpact/output/postprocessing.h>
#include <fgimpact/output/results.h>
#include <fgimpact/plate/plate_fields.h>
#include <fgimpact/plate/plate_model.h>
#include <fgimpact/plate/probe_set.h>
#include <fgimpact/plate/probes.h>
#include <fgimpact/time/contact_coupler.h>
#include <fgimpact/time/time_stepper.h>

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace fgimpact
{
  using namespace dealii;

  /// Subsection "Output": where and how often the monitor writes.
  struct OutputParameters
  {
    std::string  directory       = "output";
    unsigned int vtu_interval    = 0;
    unsigned int log_interval    = 50;
    bool         print_timing    = true;
    bool         instrumentation = false;
    bool         overwrite       = true;
    /// Entry "Checkpoint interval" (steps; 0 = none).
    unsigned int checkpoint_interval = 200;

    /// Entry "VTU compression" (zlib level of the VTU data).
    DataOutBase::VtkFlags::ZlibCompressionLevel vtu_compression =
      DataOutBase::VtkFlags::best_speed;
    /// Entry "Fields" (what the VTU files hold).
    VtuFields vtu_fields;
    /// Entry "Probe points" (probes.csv).
    ProbePoints probe_points;

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);
  };



  /// Everything history.csv shows at one time, in SI units.
  struct HistorySample
  {
    double                t       = 0; // s
    const ImpactorState  *ball    = nullptr;
    const ContactState   *contact = nullptr;
    double                W_mid = 0, W_top = 0; // m, positive down
    SymmetricTensor<2, 3> sigma_mid;            // Pa
    double E_impactor = 0, E_kinetic = 0, E_strain = 0, E_contact = 0; // J
    double E_total = 0;                                                // J
  };

  /**
   * What history.csv shows of the plate at one time (SI units): the probes'
   * values, which are linear functionals of the displacement, and the
   * plate's energies.  ImpactMonitor::record() takes them from a time
   * stepper; the study's convolution engine from sums of unit responses.
   */
  struct PlateSample
  {
    double                W_mid = 0, W_top = 0;        // m, positive down
    SymmetricTensor<2, 3> sigma_mid;                   // Pa
    double                E_kinetic = 0, E_strain = 0; // J
    unsigned int          linear_iterations = 0;
  };

  /// Where history.csv's probes are (m): the mid-plane and the top-face
  /// points at the plate's centre, in this order.
  std::array<Point<3>, 2>
  history_probe_points(const PlateGeometry &geometry);

  /// The probes' values (mid-plane, top) for the plate displacement u (m);
  /// energies 0.  Collective.
  PlateSample
  probe_plate(const PointProbe                    &mid,
              const PointProbe                    &top,
              const TrilinosWrappers::MPI::Vector &u);

  /// One column of history.csv: name (with unit), decimals, and the value
  /// in the file's unit.
  struct HistoryColumn
  {
    const char *name;
    int         decimals;
    double (*value)(const HistorySample &);
  };

  /// The columns of history.csv, declared once (the CSV header, the rows
  /// and the docs follow this list).
  const std::vector<HistoryColumn> &
  history_columns();

  /// The columns a resolved contact adds after history_columns():
  /// contact_radius_mm, max_contact_pressure_MPa, n_contact_nodes.
  const std::vector<HistoryColumn> &
  contact_area_columns();



  /**
   * Watches an impact run: evaluates the probes and energies at every step,
   * keeps the results (peak force by a parabola through the largest sample
   * and its neighbours, contact episodes, impulse, maxima), streams
   * history.csv (nothing kept in memory; observers may subscribe to the
   * rows), writes the VTU snapshots and the log lines, and at the end
   * summary.txt.  The results go into the driver's ImpactResults, whose
   * set-up entries (masses, DoFs, contact constants, timings) the driver
   * fills.  Only rank 0 writes files; every rank computes.
   *
   * It also watches the energy balance: one warning past a relative drift
   * of 1e-2, and ExcNumericalFailure (naming the time step and what to
   * change) past 0.5, a run that is blowing up.  A failed output write
   * does not throw on the failing rank alone: it is kept in
   * output_failure(), which the driver combines over the ranks.
   */
  class ImpactMonitor
  {
  public:
    using RowObserver = std::function<void(const std::vector<double> &)>;

    ImpactMonitor(const OutputParameters &parameters,
                  const PlateModel       &plate,
                  const ContactModel     &contact,
                  const double            impactor_mass,
                  const double            impact_velocity,
                  const double            dt,
                  const unsigned int      n_steps,
                  ImpactResults          &results,
                  CheckpointReader       *resume = nullptr);

    /// Receive every history row (the CSV's columns and units, before
    /// rounding) on every rank.
    void
    add_row_observer(const RowObserver &observer);

    /// With VTU output: also the ball (a sphere of the given radius, m,
    /// first touching the top face at impact_point) and the contact nodes
    /// (ContactVtuWriter).
    void
    add_contact_output(const Point<3> &impact_point,
                       const double    sphere_radius);

    /// Record the state at step (time t, s) after the stepper advanced.
    void
    record(const unsigned int   step,
           const double         t,
           const TimeStepper   &stepper,
           const ImpactorState &ball,
           const ContactState  &contact);

    /// The same with the plate given as a sample; probes and VTU snapshots
    /// only if the fields (constraints distributed) are given.
    void
    record(const unsigned int   step,
           const double         t,
           const PlateSample   &plate,
           const ImpactorState &ball,
           const ContactState  &contact,
           const PlateFields   *fields = nullptr);
    /// The layout of save()'s checkpoint section.
    static constexpr std::uint32_t checkpoint_version = 1;

    /**
     * For a checkpoint: the monitor's state (the time history's results,
     * peak detection, episodes, the contact work, the watchdog), the
     * length of history.csv (flushed) and the PVD entries so far.  A
     * failed write is kept in output_failure() as in record().
     */
    void
    save(CheckpointWriter &out, const unsigned int step);

    /// A resumed run, once the state is restored: write the VTU snapshot
    /// of the checkpoint's step again if it was still being written when
    /// the checkpoint was taken.
    void
    resume_output(const unsigned int step,
                  const double       t,
                  const TimeStepper &stepper);

    /// Wait for the last VTU snapshot and flush history.csv (timed as
    /// output).
    void
    close_output();

    /// The message of a failed output write on this rank ("" if none).
    const std::string &
    output_failure() const
    {
      return output_failure_message;
    }

    /**
     * Derive the final results after steps_done time steps, print them
     * and write summary.txt with `status` (completed, interrupted or
     * failed); loop_time and wall_time (s) are the driver's clocks.
     */
    void
    finish(const ImpactorState &ball,
           const unsigned int   steps_done,
           const std::string   &status,
           const double         loop_time,
           const double         wall_time);

  private:
    /// One log line at the first step whose LCP needed the fallback.
    void
    report_lcp_fallback(const unsigned int  step,
                        const double        t,
                        const ContactState &contact);

    /// Rank 0: history.csv and probes.csv, new or continued from the
    /// checkpoint's lengths; a failure is kept in output_failure().
    void
    open_csv_files();

    /// The constructor's part of a resume: save()'s state, the history
    /// length in history_length; the PVD entries are restored by the
    /// writers.
    void
    load(CheckpointReader &in);

    void
    update_episodes(const double t, const ContactState &contact);
    void
    update_extremes(const double t, const HistorySample &sample);
    void
    watch_energy(const unsigned int step, const double t, const double drift);
    void
    write_outputs(const unsigned int   step,
                  const double         t,
                  const PlateFields   *fields,
                  const HistorySample &sample);
    void
    print_results() const;
    void
    write_summary(const std::string &status, const double t_end) const;

    const OutputParameters parameters;
    const ContactModel    &contact_model;
    const double           m_i, V0, E0, dt;
    const unsigned int     n_steps;
    const bool             root;
    /// 1 / PlateGeometry::share(): the whole plate's sums per part sum.
    const double whole;
    /// The contact of the current step with the whole plate's force.
    ContactState       whole_contact;
    bool               lcp_fallback_reported = false;
    ConditionalOStream pcout;
    ImpactResults     &impact_results;

    PointProbe mid_probe, top_probe;
    /// The stepper's fields with the constraints distributed: every
    /// probe, VTU snapshot and peak field reads these.
    PlateFields                fields;
    std::unique_ptr<CsvWriter> history;
    /// probes.csv: the probe points and the support reaction.
    std::unique_ptr<ProbeSet>         probe_set;
    std::unique_ptr<CsvWriter>        probe_csv;
    std::vector<double>               probe_row;
    std::unique_ptr<VtuWriter>        vtu;
    std::unique_ptr<ContactVtuWriter> contact_vtu;
    std::vector<RowObserver>          observers;
    /// history_columns(), plus contact_area_columns() for a resolved
    /// contact.
    std::vector<HistoryColumn> columns;
    Timer                      output_timer;
    ProgressMeter              progress;

    // Contact episodes: alpha(0) = 0 with alpha' > 0 counts as contact.
    bool   in_contact     = true;
    bool   separated_once = false;
    double last_force = 0, last_alpha = 0;
    /// Models without a potential: approach at the top node (m) and the
    /// contact force's work on it (J).
    double   last_approach = 0, contact_work = 0;
    MPI_Comm plate_communicator = MPI_COMM_WORLD;
    // Peak detection: the sample left of the largest one.
    double peak_left    = 0;
    bool   peak_pending = false;
    // The energy watchdog has warned; an output write failed on this rank.
    bool        drift_warned = false;
    std::string output_failure_message;
    /// A resumed run: history.csv's length and the PVD entries at the
    /// checkpoint.
    std::uintmax_t history_length = 0;
    /// probes.csv's length at the checkpoint (0: no probes).
    std::uintmax_t                              probe_length = 0;
    std::vector<std::pair<double, std::string>> vtu_records, sphere_records,
      contact_records;
    bool rewrite_snapshot = false;
  };
} // namespace fgimpact

#endif
