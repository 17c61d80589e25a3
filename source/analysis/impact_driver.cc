// The impact time loop (ImpactDriver::run(), step-18 shape), its end and its
// failure paths; the set-up is in impact_driver_setup.cc, the checkpoints in
// impact_driver_checkpoint.cc.

#include <deal.II/lac/solver_control.h>

#include <fgimpact/analysis/impact_driver.h>
#include <fgimpact/analysis/impact_setup.h>
#include <fgimpact/base/exceptions.h>
#include <fgimpact/base/stop_signals.h>
#include <fgimpact/contact/compliance.h>
#include <fgimpact/output/impact_summary.h>
#include <fgimpact/output/plasticity_report.h>
#include <fgimpact/output/validity_report.h>
#include <fgimpact/problem/scene.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <limits>
#include <sstream>

namespace fgimpact
{
  namespace
  {
    /// The message of a failed output write in f ("" if none).
    template <typename F>
    std::string
    failure_of(const F &f)
    {
      try
        {
          f();
        }
      catch (const ExcOutputFailure &e)
        {
          return one_line(message_of(e));
        }
      return "";
    }

    /// The one line after SIGINT/SIGTERM, with how to resume.
    std::string
    interruption_message(const int          stop,
                         const unsigned int steps_done,
                         const unsigned int n_steps,
                         const double       dt,
                         const std::string &directory,
                         const std::string &checkpoint_failure,
                         const unsigned int n_ranks)
    {
      char text[400];
      std::snprintf(text,
                    sizeof(text),
                    "interrupted by %s after time step %u of %u (t = %.3f "
                    "us); history.csv, solution.pvd and summary.txt "
                    "(status = interrupted) are complete; ",
                    signal_name(stop),
                    steps_done,
                    n_steps,
                    steps_done * dt * 1e6);
      // A checkpoint is resumed on as many ranks as wrote it.
      const std::string launcher =
        n_ranks > 1 ? "mpirun -n " + std::to_string(n_ranks) + " " : "";
      return text + (checkpoint_failure.empty() ?
                       "continue with: " + launcher + "fgimpact --resume " +
                         directory :
                       "no checkpoint (" + checkpoint_failure + ")");
    }
  } // namespace



  void
  ImpactDriver::add_row_observer(const ImpactMonitor::RowObserver &observer)
  {
    observers.push_back(observer);
  }



  void
  ImpactDriver::run()
  {
    // SIGINT/SIGTERM only set a flag from here on (before history.csv
    // exists, so that its existence tells a test that the loop can be
    // stopped).
    const SignalGuard signals;
    // A resumed run restores the state of the checkpoint first (the
    // monitor reads its part when it reopens the output files).
    const std::unique_ptr<CheckpointReader> resume = load_checkpoint();
    open_monitor(resume.get());
    add_refinement_indicator();
    // Plain timers (not TimerOutput, whose destructor writes to the screen
    // when an exception such as a Newton failure is on its way out).  The
    // loop timer includes the initial state's output, which the monitor
    // counts as output time (time_loop_s = loop - output stays >= 0).
    Timer loop_timer;

    unsigned int steps_done = resume ? resume->step : 0;
    int          stop       = 0;
    std::string  checkpoint_failure;
    try
      {
        stop = run_and_close(resume.get(), steps_done, checkpoint_failure);
      }
    catch (...)
      {
        // After a numerical failure the ball's velocity means nothing: its
        // departure (3.0 m/s from 1 m/s on a 1 um ball) is no result.
        if (is_numerical_failure(std::current_exception()))
          monitor->void_ball_results();
        finish_failed_run(steps_done, loop_timer.wall_time());
        throw;
      }
    loop_timer.stop();
    if (stop < 0)
      stop_on_output_failure(steps_done, loop_timer.wall_time());

    monitor->finish(ball,
                    steps_done,
                    stop > 0 ? "interrupted" : "completed",
                    loop_timer.wall_time(),
                    total_timer.wall_time());
    report_checkpoints(loop_timer.wall_time());
    if (stop > 0)
      throw RunInterrupted(
        stop,
        interruption_message(stop,
                             steps_done,
                             n_steps,
                             dt,
                             parameters.output.directory,
                             checkpoint_failure,
                             Utilities::MPI::n_mpi_processes(
                               plate.get_mpi_communicator())));
  }



  int
  ImpactDriver::run_and_close(const CheckpointReader *resume,
                              unsigned int           &steps_done,
                              std::string            &checkpoint_failure)
  {
    if (resume)
      monitor->resume_output(resume->step, resume->step * dt, *stepper);
    else
      monitor->record(0, 0., *stepper, ball, contact_state);
    int stop = run_steps(steps_done);
    // SIGINT/SIGTERM: a checkpoint at the stop, whatever the interval (a
    // failure to write it does not hide the interruption).
    if (stop > 0)
      checkpoint_failure = failure_of([&]() {
        AssertThrow(write_checkpoint(steps_done) == 0,
                    ExcOutputFailure(monitor->output_failure()));
      });
    report_end_time(stop, steps_done);
    monitor->close_output();
    if (agreed_stop(plate.get_mpi_communicator(),
                    !monitor->output_failure().empty()) < 0)
      stop = -1;
    return stop;
  }



  int
  ImpactDriver::run_steps(unsigned int &steps_done)
  {
    // SIGINT/SIGTERM and failed writes are looked at once per step, agreed
    // over the ranks (one all-reduce of an int), so all stop together.
    const MPI_Comm     comm     = plate.get_mpi_communicator();
    const unsigned int interval = parameters.output.checkpoint_interval;
    int                stop     = 0;
    while (steps_done < n_steps && stop == 0)
      {
        timestep            = steps_done + 1;
        const bool finished = do_timestep();
        steps_done          = timestep;
        stop = agreed_stop(comm, !monitor->output_failure().empty());
        if (finished)
          break;
        if (stop == 0 && interval > 0 && steps_done % interval == 0 &&
            steps_done < n_steps)
          stop = write_checkpoint(steps_done);
      }
    return stop;
  }



  void
  ImpactDriver::open_monitor(CheckpointReader *resume)
  {
    // The monitor opens the output files: only now, after setup() passed.
    monitor = std::make_unique<ImpactMonitor>(parameters.output,
                                              plate,
                                              *contact,
                                              impactor.mass(),
                                              impactor.initial_velocity(),
                                              dt,
                                              n_steps,
                                              results,
                                              summary_file,
                                              plasticity != nullptr);
    if (plasticity)
      monitor->set_plasticity(*plasticity);
    // A thermal pre-stress: every stress written is the total.
    if (thermal_state)
      monitor->set_prestress(thermal_state->initial_stress());
    monitor->set_blow_up_advice(blow_up_advice());
    // End time = auto: the plate's compliance makes the contact longer
    // than Hertz's on a rigid base (the default scene: contact 126 us against
    // Hertz's 99 us, end 158 us)
    // and the rule waits a quarter of it after the ball left.
    constexpr double expected_duration_factor = 1.6;
    if (parameters.time_integration.auto_end_time)
      monitor->expect_steps(static_cast<unsigned int>(
        std::ceil(expected_duration_factor * hertz_contact_duration() / dt)));
    for (const auto &observer : observers)
      monitor->add_row_observer(observer);
    monitor->add_field_output(scene.impact_point(),
                              impactor.radius(),
                              plasticity.get());
    // The plastic results first: the validity line the ValidityMonitor
    // prints at the end reads the largest plastic strain.
    if (plasticity)
      monitor->add(
        std::make_unique<PlasticityReport>(*plasticity,
                                           plate,
                                           results,
                                           1. / scene.share(),
                                           impactor.initial_velocity(),
                                           scene.impact_point(),
                                           impactor.radius()));
    auto validity = std::make_unique<ValidityMonitor>(
      plate,
      validity_setup(parameters, scene, *contact, results),
      results,
      pcout,
      plasticity.get());
    // A thermal pre-stress: the indices of the total stress.
    if (thermal_state)
      validity->set_prestress(thermal_state->initial_stress());
    monitor->add(std::move(validity));
    monitor->start(resume);
    if (resume)
      accept_resume();
    // Rank 0 alone has opened history.csv (and probes.csv): every rank
    // learns whether that worked before the first collective output.
    stop_on_output_failure(resume ? resume->step : 0, 0.);
  }



  void
  ImpactDriver::accept_resume() const
  {
    // A resume whose files cannot be continued is refused before anything
    // is written: summary.txt and every other file stay as they were.
    const std::string refusal = monitor->agreed_output_failure();
    AssertThrow(refusal.empty(),
                ExcResumeRefused("--resume " + parameters.output.directory +
                                 ": " + refusal +
                                 "; the run's files are left as they were"));
    if (checkpoint_settings.on_resume_accepted)
      checkpoint_settings.on_resume_accepted();
  }



  void
  ImpactDriver::note_end_time() const
  {
    // A given step that does not divide End time: the last step ends
    // after it (a computed, explicit step never divides it: no note).
    const auto &ti = parameters.time_integration;
    if (!ti.auto_end_time && ti.time_step > 0 &&
        n_steps * dt > ti.end_time * (1. + 1e-9))
      pcout << "  note: Time integration/End time (" << ti.end_time * 1e6
            << " us) is not a whole number of time steps of " << dt * 1e6
            << " us: the run ends at " << n_steps * dt * 1e6 << " us\n";
  }



  void
  ImpactDriver::finish_failed_run(const unsigned int steps_done,
                                  const double       loop_time)
  {
    try
      {
        monitor->close_output();
        monitor->finish(
          ball, steps_done, "failed", loop_time, total_timer.wall_time());
      }
    catch (...)
      {}
  }



  void
  ImpactDriver::stop_on_output_failure(const unsigned int steps_done,
                                       const double       loop_time)
  {
    const MPI_Comm comm = plate.get_mpi_communicator();
    if (agreed_stop(comm, !monitor->output_failure().empty()) >= 0)
      return;
    // A failed write (disk full): summary.txt marked failed if it can
    // still be written, then one line naming the file, which rank 0
    // learns from the failing rank (all ranks are here together).
    finish_failed_run(steps_done, loop_time);
    std::string message;
    for (const auto &m :
         Utilities::MPI::all_gather(comm, monitor->output_failure()))
      if (message.empty())
        message = m;
    AssertThrow(false, ExcOutputFailure(message));
  }



  void
  ImpactDriver::write_failed_summary(const std::string &status) const
  {
    if (monitor || !checkpoint_settings.resume_directory.empty())
      return;
    // The time history has not started: its maxima are 0, and the ball
    // has not left (contact_duration and departure_velocity are none).
    ImpactResults r      = results;
    r.contact_duration   = std::numeric_limits<double>::quiet_NaN();
    r.departure_velocity = std::numeric_limits<double>::quiet_NaN();
    r.wall_time          = total_timer.wall_time();
    summary_file.write(
      impact_summary(r,
                     contact && contact->reports_contact_area(),
                     parameters.output.instrumentation,
                     status,
                     0.));
  }



  bool
  ImpactDriver::do_timestep()
  {
    const double t = timestep * dt;
    coupler->advance(timestep, t, ball, contact_state);
    monitor->record(timestep, t, *stepper, ball, contact_state);
    if (!parameters.time_integration.auto_end_time)
      {
        end_time_rule.record(t, contact_state.force);
        return false;
      }
    return end_time_rule.left_for_good(t,
                                       ball.w,
                                       ball.v,
                                       contact_state.force,
                                       stepper->kinetic_energy() +
                                         stepper->strain_energy(),
                                       [this]() { return static_compliance; });
  }



  void
  ImpactDriver::report_end_time(const int stop, const unsigned int steps_done)
  {
    if (!parameters.time_integration.auto_end_time || stop != 0)
      return;
    // Snapshot times the automatic end left behind: not written, said in
    // the log and in summary.txt's warnings.
    std::ostringstream dropped;
    for (const double t : parameters.output.snapshot_times)
      if (t > steps_done * dt * (1. + 1e-12))
        dropped << (dropped.str().empty() ? "" : ", ") << t * 1e6;
    if (!dropped.str().empty())
      {
        std::ostringstream warning;
        warning << "Output/Snapshot times after the automatic end at "
                << steps_done * dt * 1e6 << " us not written (" << dropped.str()
                << " us)";
        pcout << "  WARNING: " << warning.str() << ".\n";
        results.warnings.push_back(warning.str());
      }
    // (The rule may fire at the last step too.)
    if (end_time_rule.has_stopped())
      pcout << "  " << end_time_rule.reason() << '\n';
    else
      pcout << "  WARNING: End time = auto: the ball had not left the plate "
               "for good by Time integration/Maximum end time ("
            << parameters.time_integration.end_time * 1e6
            << " us); the run stopped there; raise it to see the rest.\n";
  }
} // namespace fgimpact
