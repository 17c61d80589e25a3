#ifndef fgimpact_monitor_h
#define fgimpact_monitor_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/timer.h>

#include <fgimpact/base/checkpoint.h>
#include <fgimpact/base/logger.h>
#include <fgimpact/contact/contact_model.h>
#include <fgimpact/output/contact_output.h>
#include <fgimpact/output/output_files.h>
#include <fgimpact/output/postprocessing.h>
#include <fgimpact/output/postprocessors.h>
#include <fgimpact/output/results.h>
#include <fgimpact/plate/plate_model.h>
#include <fgimpact/plate/probe_set.h>
#include <fgimpact/plate/probes.h>
#include <fgimpact/time/contact_coupler.h>
#include <fgimpact/time/plate_fields.h>
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
    /// Entry "Report": report.html at the end (write_run_report()).
    bool report = true;
    /// Entry "Checkpoint interval" (steps; 0 = none).
    unsigned int checkpoint_interval = 200;

    /// Entry "Snapshot times" (s, ascending) and
    /// "Snapshot at peak force".
    std::vector<double> snapshot_times;
    bool                peak_snapshot = true;

    /// Whether any VTU series is written.
    bool
    writes_vtu() const
    {
      return vtu_interval > 0 || !snapshot_times.empty();
    }

    /// Entry "VTU compression" (no_compression: raw binary VTU data).
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
    /// The plastic work (J) and largest equivalent plastic strain.
    double       E_plastic = 0, max_plastic_strain = 0;
    unsigned int linear_iterations = 0;
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

  /**
   * Watches an impact run: builds at every recorded step what history.csv
   * shows (the probes at the plate's centre, the energies, the whole
   * plate's values when a symmetric part is modelled) and hands it to a
   * list of postprocessors, each with one job (postprocessors.h): the
   * results, the energy watchdog, history.csv, probes.csv, the VTU series
   * and the screen log.  At the end it writes summary.txt.  The results
   * go into the driver's ImpactResults, whose set-up entries (masses,
   * DoFs, contact constants, timings) the driver fills.  Only rank 0
   * writes the CSV files; every rank computes.
   *
   * Life cycle: construct, add postprocessors, start() (a resumed run's
   * state, then the files), record() at every step, save() for a
   * checkpoint, close_output(), finish().
   */
  class ImpactMonitor
  {
  public:
    using RowObserver = HistoryWriter::RowObserver;

    /// The standard postprocessors: results, energy watchdog, history.csv
    /// and probes.csv (if Output/Probe points has any).
    ImpactMonitor(const OutputParameters &parameters,
                  const PlateModel       &plate,
                  const ContactModel     &contact,
                  const double            impactor_mass,
                  const double            impact_velocity,
                  const double            dt,
                  const unsigned int      n_steps,
                  ImpactResults          &results,
                  SummaryFile            &summary,
                  const bool              plastic = false);

    /// A plastic run: the probes' stresses are the ones the material
    /// carries, as the VTU's.
    void
    set_plasticity(const PlasticPlate &plasticity);

    /// A thermal run: the probes' stresses (history.csv, probes.csv and
    /// their peaks) and, in add_field_output(), the VTU's are the total,
    /// the initial state's plus the impact's.  Before add_field_output();
    /// collective.
    void
    set_prestress(const InitialStress &initial);

    /// Receive every history row (the CSV's columns and units, before
    /// rounding) on every rank.
    void
    add_row_observer(const RowObserver &observer);

    /// What the one line of a run that blows up advises (the energy
    /// watchdog's): the driver knows the scheme and Hertz's duration.
    void
    set_blow_up_advice(const std::string &text)
    {
      blow_up_advice = text;
    }

    /// The ball's departure and the contact's duration of a run that
    /// failed numerically are no results: summary.txt gives none.
    void
    void_ball_results()
    {
      ball_results_void = true;
    }

    /// Append a postprocessor (before start()).
    void
    add(std::unique_ptr<Postprocessor> postprocessor);

    /// With Output/VTU interval > 0: the VTU series of the plate, the ball
    /// (a sphere of the given radius, m, first touching the top face at
    /// impact_point) and the contact nodes (FieldWriter).
    void
    add_field_output(const Point<3>     &impact_point,
                     const double        sphere_radius,
                     const PlasticPlate *plasticity = nullptr);

    /// End time = auto (before start()): the progress meter counts to this
    /// many steps, expected, not the Maximum end time's n_steps.
    void
    expect_steps(const unsigned int steps)
    {
      expected_steps = steps;
    }

    /**
     * A resumed run: every postprocessor loads its section of `resume`
     * first.  Then the files are opened, new or continued.  A failure to
     * open one is kept in output_failure().
     */
    void
    start(const CheckpointReader *resume = nullptr);

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

    /// The layout of the monitor's own checkpoint section.
    static constexpr std::uint32_t checkpoint_version = 2;

    /**
     * For a checkpoint: the section "monitor" (the contact work of a model
     * without a potential) and one section "monitor: NAME" per
     * postprocessor with state (the results, the watchdog, the files'
     * lengths, flushed, and the PVD entries).  A failed write is kept in
     * output_failure() as in record().
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

    /// Wait for the last VTU snapshot and flush the CSV files (timed as
    /// output).
    void
    close_output();

    /// The message of a failed output write on this rank ("" if none).
    const std::string &
    output_failure() const;

    /// The message of a failed output write on the lowest rank that has
    /// one ("" if none): every rank gets the same (collective).
    std::string
    agreed_output_failure() const;

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
    std::string blow_up_advice =
      "reduce Time integration/Time step, or lower Time integration/Stable "
      "step safety factor";
    bool ball_results_void = false;

    /// The name of a postprocessor's checkpoint section.
    static std::string
    section_name(const Postprocessor &postprocessor);

    /// The whole plate's sample of this step.
    HistorySample
    make_sample(const unsigned int   step,
                const double         t,
                const PlateSample   &plate,
                const ImpactorState &ball,
                const ContactState  &part_contact);

    void
    print_results() const;

    const OutputParameters parameters;
    const PlateModel      &plate;
    const ContactModel    &contact_model;
    const double           m_i, V0, E0, dt;
    const unsigned int     n_steps;
    unsigned int           expected_steps = 0; // 0: n_steps
    /// 1 / PlateGeometry::share(): the whole plate's sums per part sum.
    const double whole;
    /// The contact of the current step with the whole plate's force.
    ContactState       whole_contact;
    ConditionalOStream pcout;
    ImpactResults     &impact_results;
    SummaryFile       &summary;

    PointProbe mid_probe, top_probe;
    /// The Output/Probe points (owned by their ProbeWriter), or null.
    ProbeSet *probe_set = nullptr;
    /// set_prestress(); null without a thermal state.
    const InitialStress *initial_stress = nullptr;
    /// The stepper's fields with the constraints distributed: every
    /// probe, VTU snapshot and peak field reads these.
    PlateFields fields;
    /// In the order they run at every step.
    std::vector<std::unique_ptr<Postprocessor>> postprocessors;
    HistoryWriter                              *history = nullptr;
    /// The results, for the snapshot at the peak force.
    const ResultsAccumulator *results_accumulator = nullptr;
    Timer                     output_timer;

    /// Models without a potential: the contact force (N) and approach at
    /// the top node (m) of the last step, and the force's work on it (J).
    double last_force = 0, last_approach = 0, contact_work = 0;
  };
} // namespace fgimpact

#endif
