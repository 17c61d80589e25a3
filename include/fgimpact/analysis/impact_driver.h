#ifndef fgimpact_impact_driver_h
#define fgimpact_impact_driver_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <fgimpact/analysis/thermal_step.h>
#include <fgimpact/base/checkpoint.h>
#include <fgimpact/contact/contact_law.h>
#include <fgimpact/contact/contact_model.h>
#include <fgimpact/contact/impactor.h>
#include <fgimpact/output/monitor.h>
#include <fgimpact/plate/plate_model.h>
#include <fgimpact/plate/refinement_indicator.h>
#include <fgimpact/problem/parameters.h>
#include <fgimpact/problem/scene.h>
#include <fgimpact/time/auto_end_time.h>
#include <fgimpact/time/contact_coupler.h>
#include <fgimpact/time/time_stepper.h>

#include <memory>
#include <vector>

namespace fgimpact
{
  using namespace dealii;

  /**
   * A problem type's driver, given the plate that all of them share:
   * setup() builds and checks everything and writes no file; run()
   * computes and writes the outputs.
   */
  class ProblemDriver
  {
  public:
    virtual ~ProblemDriver() = default;

    virtual void
    setup() = 0;

    virtual void
    run() = 0;

    /// After a failure that left no summary.txt behind (in set-up,
    /// or in run() before its own outputs): summary.txt with status =
    /// failed.  Throws ExcOutputFailure if it cannot be written.
    virtual void
    write_failed_summary(const std::string &status = "failed") const = 0;
  };



  /**
   * The low-velocity impact (Problem type = impact), in the shape of
   * step-18: setup() builds the contact model and the time stepper, run()
   * records the initial state and calls do_timestep() until the end time.
   * The ContactCoupler advances plate (the TimeStepper's response), ball
   * and contact by a step; the ImpactMonitor watches the state and writes
   * every output.
   */
  class ImpactDriver : public ProblemDriver
  {
  public:
    ImpactDriver(const Parameters &parameters,
                 const Scene      &scene,
                 const PlateModel &plate,
                 const Timer      &total_timer,
                 SummaryFile      &summary);

    void
    setup() override;

    void
    run() override;

    /// Every summary.txt key, with the set-up's entries (masses, DoFs,
    /// contact constants) and time_reached_us = 0; nothing when the
    /// monitor exists (it wrote its own) or when resuming (the run being
    /// continued keeps its files).
    void
    write_failed_summary(const std::string &status = "failed") const override;

    /// Subscribe to the history rows (before run()).
    void
    add_row_observer(const ImpactMonitor::RowObserver &observer);

    /// The thermal step before this impact (Thermal/Temperature field):
    /// every stress written and the validity indices are the total, its
    /// stress plus the impact's. Before
    /// setup(); it must outlive the driver.
    void
    set_thermal_state(const ThermalStep &thermal)
    {
      thermal_state = &thermal;
    }

    /// Accumulate `indicator` (RefinementIndicator::add() with the step's
    /// length) at every step of run(); before run(), it must outlive it.
    void
    set_refinement_indicator(RefinementIndicator &indicator)
    {
      refinement_indicator = &indicator;
    }

    /// Checkpoints: the parameters' text to store, and whether to resume
    /// (before run()).
    void
    set_checkpointing(const CheckpointSettings &settings);

    const ImpactResults &
    get_results() const
    {
      return results;
    }

  private:
    /// set_thermal_state(); null without a temperature field.
    const ThermalStep *thermal_state = nullptr;
    /// set_refinement_indicator(); null if none.
    RefinementIndicator *refinement_indicator = nullptr;
    /// One step, recorded; true if End time = auto and the ball has left
    /// for good (the run stops after it).
    bool
    do_timestep();

    /// End time = auto, unless a signal stopped the run (stop != 0): one
    /// log line on why the run stopped, or a warning that it ran to the
    /// Maximum end time.
    void
    report_end_time(const int stop, const unsigned int steps_done);

    /// The contact model of Contact/Model, said in the log with its
    /// warning and the elastic ball's vibration.
    void
    create_contact();

    /// The time stepper: built, its matrices factorized (a solver failure
    /// named), and with Material/Plasticity = J2 the plate's plastic
    /// state handed to it.
    void
    initialize_stepper();

    /// hertz_impact_duration() with the contact law's stiffness: a lower
    /// bound of the plate's contact duration (s).
    double
    hertz_contact_duration() const;

    /// What the line of a run that blows up advises (the scheme's remedy,
    /// with Hertz's duration against the time step).
    std::string
    blow_up_advice() const;

    /// The time step against the End time (refused if longer) and against
    /// Hertz's contact duration (a log warning below 20 steps in it).
    void
    check_time_step() const;

    /// One log line on what the contact's accuracy depends on: the mesh
    /// dependence of hertz node; a resolved sphere whose estimated contact
    /// radius spans fewer than contact_elements_per_radius elements.
    void
    note_contact_resolution();

    /// A log note when a given Time step does not divide End time (the
    /// run ends after it, at the end of its last step).
    void
    note_end_time() const;

    /// On resume, after the monitor has looked at the output files: a
    /// file that cannot be continued refuses the resume (ExcResumeRefused,
    /// every rank, nothing written); else parameters.prm is written
    /// (CheckpointSettings::on_resume_accepted).
    void
    accept_resume() const;

    /// Restore the state of the checkpoint in the output directory (the
    /// driver's part; the monitor reads the rest); returns its reader.
    std::unique_ptr<CheckpointReader>
    load_checkpoint();

    /// Write a checkpoint after step `step` (collective): -1 if an output
    /// write failed on some rank (kept in the monitor), else 0.
    int
    write_checkpoint(const unsigned int step);

    /// At the end: one line on the checkpoints written (with timing).
    void
    report_checkpoints(const double loop_time) const;

    /// The time steps from steps_done on (updated as they are done) until
    /// the end, the ball's departure for good or a stop: agreed_stop()'s
    /// value (0: none), the periodic checkpoints written.
    int
    run_steps(unsigned int &steps_done);

    /// set_refinement_indicator(): its recorder into the monitor.
    void
    add_refinement_indicator();

    /// Create the monitor (it opens the output files; on resume it
    /// continues them) with its observers and contact output; every rank
    /// stops if rank 0 could not open them.
    void
    open_monitor(CheckpointReader *resume);

    /// run()'s loop: the initial (or resumed) output, the steps, a
    /// signal's checkpoint (its failure into checkpoint_failure), the
    /// files closed; the stop agreed over the ranks (> 0: a signal, < 0: a
    /// failed output, 0: the end).
    int
    run_and_close(const CheckpointReader *resume,
                  unsigned int           &steps_done,
                  std::string            &checkpoint_failure);

    /// After a failure in the time loop: summary.txt with status = failed
    /// (best effort: errors here are swallowed, the first one counts).
    void
    finish_failed_run(const unsigned int steps_done, const double loop_time);

    /// Collective: if an output write failed on any rank, finish the run
    /// as failed and throw ExcOutputFailure with the first failing rank's
    /// message on every rank.
    void
    stop_on_output_failure(const unsigned int steps_done,
                           const double       loop_time);

    const Parameters &parameters;
    const PlateModel &plate;
    const Timer      &total_timer;
    /// summary.txt (the monitor writes it; a failed set-up here).
    SummaryFile       &summary_file;
    ConditionalOStream pcout;
    const Scene       &scene;
    const Impactor    &impactor; // the scene's
    HertzContactLaw    contact_law;
    ImpactResults      results;

    std::unique_ptr<ContactModel> contact;
    std::unique_ptr<TimeStepper>  stepper;
    /// Material/Plasticity = J2: the graded strengths and the plate's
    /// plastic state, which the stepper iterates on.
    std::unique_ptr<GradedStrength>         strength;
    std::unique_ptr<PlasticPlate>           plasticity;
    std::unique_ptr<ContactCoupler>         coupler;
    std::unique_ptr<ImpactMonitor>          monitor;
    std::vector<ImpactMonitor::RowObserver> observers;

    CheckpointSettings checkpoint_settings;
    unsigned int       n_checkpoints    = 0;
    double             checkpoint_time  = 0; // s, all checkpoints
    std::size_t        checkpoint_bytes = 0; // of rank 0's last one

    ImpactorState ball;
    ContactState  contact_state;
    AutoEndTime   end_time_rule;
    /// End time = auto: the plate's largest static compliance at the
    /// contact (m/N), the rule's C, computed in setup() before the
    /// stepper's factorization so that its own factor of K is gone
    /// before K_eff's is made (0 otherwise).
    double       static_compliance = 0;
    double       dt                = 0;
    unsigned int n_steps           = 0;
    unsigned int timestep          = 0;
  };
} // namespace fgimpact

#endif
