#ifndef fgimpact_postprocessors_h
#define fgimpact_postprocessors_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <fgimpact/base/logger.h>
#include <fgimpact/output/contact_output.h>
#include <fgimpact/output/output_files.h>
#include <fgimpact/output/postprocessing.h>
#include <fgimpact/output/postprocessor.h>
#include <fgimpact/output/results.h>
#include <fgimpact/output/snapshot_interpolation.h>
#include <fgimpact/plate/probe_set.h>

#include <functional>
#include <memory>

namespace fgimpact
{
  struct OutputParameters;

  /**
   * The results of the time history (summary.txt's): the peak force by a
   * parabola through the largest sample and its neighbours, the contact
   * episodes (duration, number of impacts), the impulse, the maxima, and
   * at the end the departure velocity and the warnings.
   */
  class ResultsAccumulator : public Postprocessor
  {
  public:
    /// m (kg) and V0 (m/s): the whole ball's; dt (s).
    ResultsAccumulator(ImpactResults            &results,
                       const ContactModel       &contact,
                       const double              m,
                       const double              V0,
                       const double              dt,
                       const bool                symmetric_part,
                       const ConditionalOStream &pcout);

    std::string
    name() const override
    {
      return "results";
    }
    /// 2: the measured approach (max_approach) added.
    std::uint32_t
    checkpoint_version() const override
    {
      return 2;
    }
    void
    execute(const StepRecord &record) override;
    void
    save(CheckpointWriter &out, const unsigned int step) override;
    void
    load(CheckpointReader &in) override;
    void
    finish(const ImpactorState &ball) override;

    /// Whether the last step resolved a new peak of the contact force
    /// (the parabola through the largest sample and its neighbours), and
    /// its time (s), as time_of_peak_force_us will give it.
    bool
    new_peak() const
    {
      return peak_resolved;
    }
    double
    peak_time() const
    {
      return results.time_of_peak_force;
    }

  private:
    void
    update_episodes(const double t, const ContactState &contact);
    void
    update_extremes(const double t, const HistorySample &sample);

    ImpactResults            &results;
    const ContactModel       &contact_model;
    const double              m, V0, dt;
    const bool                symmetric_part;
    const ConditionalOStream &pcout;
    // Contact episodes: alpha(0) = 0 with alpha' > 0 counts as contact.
    bool   in_contact     = true;
    bool   separated_once = false;
    double last_force = 0, last_alpha = 0;
    // Peak detection: the sample left of the largest one.
    double peak_left     = 0;
    bool   peak_pending  = false;
    bool   peak_resolved = false; // in the last step only: no checkpoint
  };



  /**
   * The energy balance: one warning past a relative drift of 1e-2, and
   * ExcNumericalFailure (naming the time step and what to change) past
   * 0.5, a run that is blowing up.
   */
  class EnergyWatchdog : public Postprocessor
  {
  public:
    /// advice: what to change when the run blows up (the scheme's and
    /// the time step's remedy), read when it does.
    EnergyWatchdog(const ConditionalOStream &pcout, const std::string &advice);

    std::string
    name() const override
    {
      return "energy watchdog";
    }
    void
    execute(const StepRecord &record) override;
    void
    save(CheckpointWriter &out, const unsigned int step) override;
    void
    load(CheckpointReader &in) override;

  private:
    const ConditionalOStream &pcout;
    const std::string        &advice;
    bool                      warned = false;
  };



  /**
   * A CSV file that grows by one row per step (CsvWriter: rank 0 writes,
   * rows handed to the disk whole), continued from its checkpointed
   * length on resume.  Its checkpoint section is the file's length
   * (flushed).  A failed write drops the file and is kept in
   * output_failure().
   */
  class CsvPostprocessor : public Postprocessor
  {
  public:
    /// filename: in the output directory; columns: name and decimals.
    CsvPostprocessor(const std::string                              &filename,
                     const std::vector<std::pair<std::string, int>> &columns,
                     const bool                                      root);

    std::string
    name() const override
    {
      return filename.substr(filename.find_last_of('/') + 1);
    }
    void
    start() override;
    void
    save(CheckpointWriter &out, const unsigned int step) override;
    void
    load(CheckpointReader &in) override;
    void
    close_output() override;

  protected:
    /// Rank 0 writes it (a no-op elsewhere, or after a failure).
    void
    write_row(const std::vector<double> &row);

  private:
    const std::string                              filename;
    const std::vector<std::pair<std::string, int>> columns;
    const bool                                     root;
    std::unique_ptr<CsvWriter>                     csv;
    std::uintmax_t                                 resume_length = 0;
  };



  /**
   * history.csv, streamed (nothing kept in memory; observers may
   * subscribe to the rows, before rounding, on every rank).
   */
  class HistoryWriter : public CsvPostprocessor
  {
  public:
    using RowObserver = std::function<void(const std::vector<double> &)>;

    HistoryWriter(const std::string                &directory,
                  const std::vector<HistoryColumn> &columns,
                  const bool                        root);

    void
    add_observer(const RowObserver &observer);

    void
    execute(const StepRecord &record) override;

  private:
    const std::vector<HistoryColumn> columns;
    std::vector<RowObserver>         observers;
    std::vector<double>              row;
  };



  /**
   * probes.csv: Output/Probe points (ProbeSet) and the support reaction,
   * at every step that has fields; and each probe's peak von Mises stress
   * (ImpactResults::probe_peaks, the same on every rank).  Every rank
   * evaluates (collective); rank 0 writes.
   */
  class ProbeWriter : public CsvPostprocessor
  {
  public:
    /// whole: 1 / the part's share (the supports' reaction is scaled up);
    /// peaks: where the peaks go.
    ProbeWriter(std::unique_ptr<const ProbeSet>        probes,
                std::vector<ImpactResults::ProbePeak> &peaks,
                const std::string                     &directory,
                const double                           whole,
                const bool                             root);

    /// 2: the peaks after the file's length (1: the length alone).
    std::uint32_t
    checkpoint_version() const override
    {
      return 2;
    }
    bool
    needs_rates(const unsigned int) const override
    {
      return true;
    }
    void
    execute(const StepRecord &record) override;
    void
    save(CheckpointWriter &out, const unsigned int step) override;
    void
    load(CheckpointReader &in) override;

  private:
    const std::unique_ptr<const ProbeSet>  probes;
    std::vector<ImpactResults::ProbePeak> &peaks;
    const double                           whole;
  };



  /**
   * The VTU/PVD series every Output/VTU interval steps: the plate
   * (VtuWriter, written in the background), and with a ball the sphere
   * and the contact nodes (ContactVtuWriter, rank 0); at the end the peak
   * fields.
   */
  class FieldWriter : public Postprocessor
  {
  public:
    /// The plastic plate's equivalent_plastic_strain in the snapshots.
    void
    set_plasticity(const PlasticPlate &plasticity)
    {
      vtu->set_plasticity(plasticity);
    }

    /// A thermal run: the total stress and the thermal fields
    /// (VtuWriter::set_prestress()).
    void
    set_prestress(const InitialStress &initial)
    {
      vtu->set_prestress(initial);
    }

    /// impact_point: where the ball first touches the top face; radius:
    /// the ball's (m).
    /// results: for the snapshot at the peak force (nullptr: none).
    FieldWriter(const PlateModel         &plate,
                const OutputParameters   &parameters,
                const ContactModel       &contact,
                const Point<3>           &impact_point,
                const double              radius,
                const ResultsAccumulator *results);

    std::string
    name() const override
    {
      return "vtu";
    }
    /// 3: with the peak fields' state (2: without; 1: the PVD times in
    /// s, the files at the top).
    std::uint32_t
    checkpoint_version() const override
    {
      return 3;
    }
    bool
    needs_rates(const unsigned int step) const override
    {
      return interpolator || (interval > 0 && step % interval == 0);
    }
    void
    start() override;
    void
    execute(const StepRecord &record) override;
    bool
    needs_rewrite() const override;
    void
    rewrite(const unsigned int step,
            const double       t,
            const PlateFields &fields) override;
    /// The PVD entries so far, and whether the snapshot of `step` was
    /// still being written.
    void
    save(CheckpointWriter &out, const unsigned int step) override;
    void
    load(CheckpointReader &in) override;
    void
    close_output() override;
    double
    output_time() const override
    {
      return timer.wall_time();
    }

  private:
    using Records = std::vector<std::pair<double, std::string>>;

    /// The z displacement (m, up) at the contact DoFs, on every rank
    /// (collective).
    std::vector<double>
    contact_node_uz(const TrilinosWrappers::MPI::Vector &u) const;

    /// The regular snapshot of this step (the step's 5 digits).
    void
    write_regular(const StepRecord &record);

    /// The snapshots between the last two steps: Output/Snapshot times
    /// and the peak force's (interpolated, SnapshotInterpolator).
    void
    write_extras(const StepRecord &record);

    /// The snapshot of the peak force at the results' peak time, if the
    /// interpolator holds it.
    void
    write_peak(const unsigned int step);

    /// Run a write; a failure is kept and drops this rank's writers.
    void
    guarded(const std::function<void()> &write);

    /// Whether every rank still writes (collective).
    bool
    all_writing() const;

    /// One interpolated snapshot named `name` at time t (s).
    void
    write_interpolated(const std::string &name,
                       const unsigned int step,
                       const double       t);

    const unsigned int interval;
    /// Output/Snapshot times (s, ascending) and the next one to write.
    const std::vector<double> snapshot_times;
    unsigned int              next_snapshot = 0;
    const ResultsAccumulator *results;
    /// The time of the peak snapshot written (s; -1: none), the last step.
    double                                peak_written = -1;
    unsigned int                          last_step    = 0;
    std::unique_ptr<SnapshotInterpolator> interpolator;
    SnapshotInterpolator::State           interpolated;
    const MPI_Comm                        communicator;
    const ContactModel                   &contact;
    std::unique_ptr<VtuWriter>            vtu;
    std::unique_ptr<ContactVtuWriter>     contact_vtu;
    Records vtu_records, sphere_records, contact_records;
    bool    resumed = false, rewrite_snapshot = false;
    Timer   timer;
  };



  /**
   * The screen: a line every Output/Log interval steps, the progress
   * meter, and one note at the first step whose contact solve needed the
   * LCP fallback.
   */
  class RunLog : public Postprocessor
  {
  public:
    RunLog(const unsigned int        log_interval,
           const unsigned int        n_steps,
           const double              E0,
           const bool                progress,
           const ConditionalOStream &pcout,
           const unsigned int        expected_steps = 0);

    void
    execute(const StepRecord &record) override;

  private:
    void
    report_lcp_fallback(const StepRecord &record);

    const unsigned int        log_interval, n_steps;
    const double              E0;
    const ConditionalOStream &pcout;
    ProgressMeter             progress;
    bool                      lcp_fallback_reported = false;
  };
} // namespace fgimpact

#endif
