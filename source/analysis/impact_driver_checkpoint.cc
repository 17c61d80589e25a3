// The impact driver's checkpoints (impact_driver.h): what it writes, how
// a resumed run reads it back, and the log line on their cost.

#include <deal.II/base/timer.h>

#include <fgimpact/analysis/impact_driver.h>
#include <fgimpact/base/stop_signals.h>

#include <cstdio>

namespace fgimpact
{
  namespace
  {
    /// ContactState field by field (it holds a vector), in a fixed order.
    template <typename Apply, typename State>
    void
    contact_state_fields(const Apply &archive, State &state)
    {
      archive(state.alpha);
      archive(state.force);
      archive(state.node_displacement);
      archive(state.newton_iterations);
      archive(state.forces);
      archive(state.n_active);
      archive(state.contact_radius);
      archive(state.max_pressure);
      archive(state.candidates_exhausted);
    }

    /// The layout of the driver's own checkpoint section (the ball and
    /// the contact state).
    constexpr std::uint32_t state_version = 1;
  } // namespace



  void
  ImpactDriver::set_checkpointing(const CheckpointSettings &settings)
  {
    checkpoint_settings = settings;
  }



  std::unique_ptr<CheckpointReader>
  ImpactDriver::load_checkpoint()
  {
    // Eq. 2.16: plate at rest, alpha(0) = 0, alpha'(0) = V0; a(0) = 0 as
    // F(0) = 0.  The impactor moves in the impact direction (-z).
    ball          = ImpactorState();
    ball.v        = impactor.initial_velocity();
    contact_state = ContactState();
    if (checkpoint_settings.resume_directory.empty())
      return nullptr;
    auto in = std::make_unique<CheckpointReader>(
      read_checkpoint(parameters.output.directory,
                      plate.get_mpi_communicator()));
    AssertThrow(in->step <= n_steps,
                ExcMessage("--resume: the checkpoint is at time step " +
                           std::to_string(in->step) +
                           ", after Time integration/End time (" +
                           std::to_string(n_steps) + " steps)"));
    // Each component's section, found by name (write_checkpoint()).  The
    // coupler must come first: it regrows the contact set, whose compliance
    // and mass the stepper's and the contact model's state refer to.
    CheckpointReader state = in->section("impact state", state_version);
    state.get(ball);
    contact_state_fields([&state](auto &value) { state.get(value); },
                         contact_state);
    CheckpointReader coupling =
      in->section("coupler", ContactCoupler::checkpoint_version);
    coupler->load(coupling);
    CheckpointReader plate_state =
      in->section("plate", TimeStepper::checkpoint_version);
    stepper->load(plate_state);
    CheckpointReader contact_model_state =
      in->section("contact model", ContactModel::checkpoint_version);
    contact->load(contact_model_state);
    CheckpointReader end_time_state =
      in->section("end time rule", AutoEndTime::checkpoint_version);
    end_time_rule.load(end_time_state);
    pcout << "  resumed from the checkpoint after "
          << time_step_label(in->step, in->step * dt) << '\n';
    return in;
  }



  int
  ImpactDriver::write_checkpoint(const unsigned int step)
  {
    Timer            timer;
    CheckpointWriter out;
    out.section("impact state", state_version, [&](CheckpointWriter &s) {
      s.put(ball);
      contact_state_fields([&s](const auto &value) { s.put(value); },
                           contact_state);
    });
    out.section("coupler",
                ContactCoupler::checkpoint_version,
                [&](CheckpointWriter &s) { coupler->save(s); });
    out.section("plate",
                TimeStepper::checkpoint_version,
                [&](CheckpointWriter &s) { stepper->save(s); });
    out.section("contact model",
                ContactModel::checkpoint_version,
                [&](CheckpointWriter &s) { contact->save(s); });
    out.section("end time rule",
                AutoEndTime::checkpoint_version,
                [&](CheckpointWriter &s) { end_time_rule.save(s); });
    monitor->save(out, step); // flushes history.csv
    const MPI_Comm comm = plate.get_mpi_communicator();
    if (agreed_stop(comm, !monitor->output_failure().empty()) < 0)
      return -1;
    fgimpact::write_checkpoint(parameters.output.directory,
                               comm,
                               step,
                               checkpoint_settings.parameters_text,
                               out.data());
    ++n_checkpoints;
    checkpoint_bytes = out.data().size();
    checkpoint_time += timer.wall_time();
    return 0;
  }



  void
  ImpactDriver::report_checkpoints(const double loop_time) const
  {
    if (n_checkpoints == 0 || !parameters.output.print_timing)
      return;
    const double per_step = loop_time / std::max(results.n_time_steps, 1u);
    const double each     = checkpoint_time / n_checkpoints;
    char         line[200];
    std::snprintf(line,
                  sizeof(line),
                  "  checkpoints: %u written, %.3f MB per rank, %.2f ms each "
                  "(%.2f time steps)\n",
                  n_checkpoints,
                  checkpoint_bytes * 1e-6,
                  each * 1e3,
                  each / per_step);
    pcout << line;
  }
} // namespace fgimpact
