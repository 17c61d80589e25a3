#include <deal.II/lac/solver_control.h>

#include <fgimpact/impact_driver.h>
#include <fgimpact/run_control.h>
#include <fgimpact/simulator.h>

#include <cmath>
#include <csignal>
#include <cstdio>

namespace fgimpact
{
  ImpactDriver::ImpactDriver(const Parameters &parameters,
                             const PlateModel &plate,
                             const Timer      &total_timer)
    : parameters(parameters)
    , plate(plate)
    , total_timer(total_timer)
    , pcout(std::cout,
            Utilities::MPI::this_mpi_process(plate.get_mpi_communicator()) == 0)
    , impactor(parameters.impactor)
    , contact_law(parameters.contact, plate.get_material(), impactor)
  {}



  void
  ImpactDriver::setup()
  {
    const PlateGeometry &geometry = plate.get_geometry();
    const double         h        = geometry.thickness();
    contact                       = create_contact_model(
      parameters.contact_model,
      contact_law,
      plate,
      impactor.radius(),
      impactor.impact_point(geometry.length(), geometry.width()),
      expected_contact_radius(parameters, plate.get_material(), h),
      top_face_modulus(plate.get_material(), h));
    pcout << "  impactor mass " << impactor.mass()
          << " kg, V0 = " << impactor.initial_velocity() << " m/s; "
          << contact->description() << '\n';
    if (!contact->warning().empty())
      pcout << "  " << contact->warning() << '\n';

    results.n_dofs = plate.n_dofs();
    results.n_mpi_ranks =
      Utilities::MPI::n_mpi_processes(plate.get_mpi_communicator());
    results.impactor_mass = impactor.mass();
    results.plate_mass    = plate.total_mass();
    contact->fill_results(results);
    results.setup_time = total_timer.wall_time();

    // The time stepper (implicit Newmark or explicit central difference)
    // builds its matrices and fixes the time step.
    Timer factorization_timer;
    stepper = create_time_stepper(parameters.time_integration,
                                  parameters.linear_solver,
                                  plate,
                                  *contact,
                                  impactor.mass(),
                                  impactor.initial_velocity());
    try
      {
        stepper->initialize(parameters.output.instrumentation);
      }
    catch (const SolverControl::NoConvergence &e)
      {
        AssertThrow(false,
                    ExcNumericalFailure(
                      "the linear solver did not converge during set-up "
                      "(the contact compliance solves) after " +
                      std::to_string(e.last_step) +
                      " iterations; raise Linear solver/Max iterations (now " +
                      std::to_string(parameters.linear_solver.max_iterations) +
                      ") or use Linear solver/Type = auto."));
      }
    results.factorization_time = factorization_timer.wall_time();
    results.spmv_time          = stepper->costs().spmv;
    results.solve_time         = stepper->costs().solve;

    dt      = stepper->time_step();
    n_steps = parameters.time_integration.n_steps(dt);
    pcout << "  " << stepper->description() << "; dt = " << dt * 1e6 << " us, "
          << n_steps << " steps\n";
    // Machine-dependent (the memory available): with the timings.
    if (parameters.output.print_timing && !stepper->solver_log().empty())
      pcout << "  " << stepper->solver_log() << '\n';

    // Can dt resolve the contact?  Hertz's duration on a rigid half-space,
    // T = 2.943 alpha_max / V0 with alpha_max = (5 m V0^2 / (4 K))^(2/5),
    // is a lower bound of the plate's (99 us against 126 us in the default
    // scene): fewer than 20 steps in it is a coarse time history.
    const double m = impactor.mass(), V0 = impactor.initial_velocity();
    const double alpha_max =
      std::pow(1.25 * m * V0 * V0 / contact_law.force(1.), 0.4);
    const double T_hertz = 2.943 * alpha_max / V0;
    if (dt > T_hertz / 20.)
      {
        char text[400];
        std::snprintf(text,
                      sizeof(text),
                      "  WARNING: Time integration/Time step = %.4g us "
                      "resolves the contact (Hertz half-space estimate %.4g "
                      "us) with only %.1f steps; use at most %.3g us.\n",
                      dt * 1e6,
                      T_hertz * 1e6,
                      T_hertz / dt,
                      T_hertz / 20. * 1e6);
        pcout << text;
      }
  }



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
    // The monitor opens the output files: only now, after setup() passed.
    monitor = std::make_unique<ImpactMonitor>(parameters.output,
                                              plate,
                                              *contact,
                                              impactor.mass(),
                                              impactor.initial_velocity(),
                                              dt,
                                              n_steps,
                                              results);
    for (const auto &observer : observers)
      monitor->add_row_observer(observer);
    const PlateGeometry &g = plate.get_geometry();
    const Point<2>       p = impactor.impact_point(g.length(), g.width());
    monitor->add_contact_output(Point<3>(p[0], p[1], g.thickness()),
                                impactor.radius());

    // Eq. 2.16: plate at rest, alpha(0) = 0, alpha'(0) = V0; a(0) = 0 as
    // F(0) = 0.  The impactor moves in the impact direction (-z).
    ball          = ImpactorState();
    ball.v        = impactor.initial_velocity();
    contact_state = ContactState();
    monitor->record(0, 0., *stepper, ball, contact_state);

    // Plain timers (not TimerOutput, whose destructor writes to the screen
    // when an exception such as a Newton failure is on its way out).
    // SIGINT/SIGTERM and failed writes are looked at once per step, agreed
    // over the ranks (one all-reduce of an int), so all stop together.
    const MPI_Comm comm = plate.get_mpi_communicator();
    Timer          loop_timer;
    unsigned int   steps_done = 0;
    int            stop       = 0;
    try
      {
        while (steps_done < n_steps && stop == 0)
          {
            timestep = steps_done + 1;
            do_timestep();
            steps_done = timestep;
            stop       = agreed_stop(comm, !monitor->output_failure().empty());
          }
        monitor->close_output();
        if (agreed_stop(comm, !monitor->output_failure().empty()) < 0)
          stop = -1;
      }
    catch (...)
      {
        finish_failed_run(steps_done, loop_timer.wall_time());
        throw;
      }
    loop_timer.stop();
    if (stop < 0)
      {
        // A failed write (disk full): summary.txt marked failed if it can
        // still be written, then one line naming the file, which rank 0
        // learns from the failing rank (all ranks are here together).
        finish_failed_run(steps_done, loop_timer.wall_time());
        std::string message;
        for (const auto &m :
             Utilities::MPI::all_gather(comm, monitor->output_failure()))
          if (message.empty())
            message = m;
        AssertThrow(false, ExcOutputFailure(message));
      }

    monitor->finish(ball,
                    steps_done,
                    stop > 0 ? "interrupted" : "completed",
                    loop_timer.wall_time(),
                    total_timer.wall_time());
    if (stop > 0)
      {
        char text[300];
        std::snprintf(text,
                      sizeof(text),
                      "interrupted by %s after time step %u of %u (t = %.3f "
                      "us); history.csv, solution.pvd and summary.txt "
                      "(status = interrupted) are complete.",
                      stop == SIGINT  ? "SIGINT" :
                      stop == SIGTERM ? "SIGTERM" :
                                        "a signal",
                      steps_done,
                      n_steps,
                      steps_done * dt * 1e6);
        throw RunInterrupted(stop, text);
      }
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
  ImpactDriver::do_timestep()
  {
    const double t = timestep * dt;
    stepper->advance(timestep, t, ball, contact_state);
    monitor->record(timestep, t, *stepper, ball, contact_state);
  }
} // namespace fgimpact
