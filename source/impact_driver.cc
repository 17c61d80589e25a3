#include <fgimpact/impact_driver.h>
#include <fgimpact/simulator.h>

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
    stepper->initialize(parameters.output.instrumentation);
    results.factorization_time = factorization_timer.wall_time();
    results.spmv_time          = stepper->costs().spmv;
    results.solve_time         = stepper->costs().solve;

    dt      = stepper->time_step();
    n_steps = parameters.time_integration.n_steps(dt);
    pcout << "  " << stepper->description() << "; dt = " << dt * 1e6 << " us, "
          << n_steps << " steps\n";
  }



  void
  ImpactDriver::add_row_observer(const ImpactMonitor::RowObserver &observer)
  {
    observers.push_back(observer);
  }



  void
  ImpactDriver::run()
  {
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
    Timer loop_timer;
    for (timestep = 1; timestep <= n_steps; ++timestep)
      do_timestep();
    monitor->close_output();
    loop_timer.stop();

    monitor->finish(ball, loop_timer.wall_time(), total_timer.wall_time());
  }



  void
  ImpactDriver::do_timestep()
  {
    const double t = timestep * dt;
    stepper->advance(timestep, t, ball, contact_state);
    monitor->record(timestep, t, *stepper, ball, contact_state);
  }
} // namespace fgimpact
