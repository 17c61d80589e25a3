// The impact driver's set-up: the contact model, the time stepper and its
// factorization, the checks of the time step and of the contact's resolution
// (the time loop is in impact_driver.cc).

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
  ImpactDriver::ImpactDriver(const Parameters &parameters,
                             const Scene      &scene,
                             const PlateModel &plate,
                             const Timer      &total_timer,
                             SummaryFile      &summary)
    : parameters(parameters)
    , plate(plate)
    , total_timer(total_timer)
    , summary_file(summary)
    , pcout(std::cout,
            Utilities::MPI::this_mpi_process(plate.get_mpi_communicator()) == 0)
    , scene(scene)
    , impactor(scene.impactor())
    , contact_law(parameters.contact, plate.get_material(), impactor)
  {}



  void
  ImpactDriver::create_contact()
  {
    contact = create_contact_model(parameters.contact_model,
                                   contact_law,
                                   plate,
                                   impactor.radius(),
                                   scene.impact_point_in_plane(),
                                   scene.expected_contact_radius(),
                                   scene.top_face_modulus(),
                                   impactor.indentation_modulus());
    pcout << "  impactor mass " << impactor.mass()
          << " kg, V0 = " << impactor.initial_velocity() << " m/s; "
          << contact->description() << '\n';
    if (!contact->warning().empty())
      pcout << "  " << contact->warning() << '\n';
    // An elastic ball: its vibration against the contact duration.
    if (!impactor.vibration_report(hertz_contact_duration()).empty())
      pcout << "  " << impactor.vibration_report(hertz_contact_duration())
            << '\n';
  }



  void
  ImpactDriver::setup()
  {
    create_contact();
    results = setup_results(plate, scene, *contact, total_timer.wall_time());

    // End time = auto's compliance factorizes K: before K_eff's factor
    // exists, not beside it (the default scene's resolved contact at level
    // 6 peaked at 475 MB when the ball left, against 396 MB without the
    // rule).
    if (parameters.time_integration.auto_end_time)
      static_compliance = largest_static_compliance(plate,
                                                    parameters.linear_solver,
                                                    contact->contact_dofs());
    initialize_stepper();
    results.spmv_time  = stepper->costs().spmv;
    results.solve_time = stepper->costs().solve;

    // The ball and the contact, coupled to the plate (on a symmetric part,
    // the part's share of the ball).
    coupler =
      std::make_unique<ContactCoupler>(*stepper,
                                       *contact,
                                       parameters.time_integration.newmark,
                                       scene.share() * impactor.mass(),
                                       parameters.time_integration.newton,
                                       plate.get_mpi_communicator());
    dt      = stepper->time_step();
    n_steps = parameters.time_integration.n_steps(dt);
    // Bad input, refused in the set-up: no file of the run is touched.
    AssertThrow(checkpoint_settings.resume_directory.empty() ||
                  checkpoint_settings.resume_step <= n_steps,
                ExcMessage("--resume: the checkpoint is at time step " +
                           std::to_string(checkpoint_settings.resume_step) +
                           ", after Time integration/End time (" +
                           std::to_string(n_steps) + " steps)"));
    pcout << "  " << stepper->description() << "; dt = " << dt * 1e6 << " us, "
          << n_steps << " steps\n";
    note_end_time();
    results.model = describe_model(parameters, scene, plate, dt);
    note_contact_resolution();
    // Machine-dependent (the memory available): with the timings.
    if (parameters.output.print_timing && !stepper->solver_log().empty())
      pcout << "  " << stepper->solver_log() << '\n';
    check_time_step();
  }



  void
  ImpactDriver::initialize_stepper()
  {
    // The time stepper (implicit Newmark or explicit central difference)
    // builds its matrices and fixes the time step.  On a symmetric part
    // the ball's share of the mass meets the part's share of the force.
    const double share = scene.share();
    Timer        factorization_timer;
    stepper = create_time_stepper(parameters.time_integration,
                                  parameters.linear_solver,
                                  plate,
                                  *contact,
                                  share * impactor.mass(),
                                  impactor.initial_velocity());
    try
      {
        stepper->initialize(parameters.output.instrumentation);
      }
    catch (const SolverControl::NoConvergence &e)
      {
        AssertThrow(
          false,
          linear_solver_failure("during set-up (the contact compliance solves)",
                                e.last_step));
      }
    catch (const ExcNumericalFailure &e)
      {
        // The factorization: name the phase.
        AssertThrow(false,
                    ExcNumericalFailure("during set-up (the effective matrix "
                                        "of the time stepper): " +
                                        message_of(e)));
      }
    results.factorization_time = factorization_timer.wall_time();
    // Material/Plasticity = J2: the plate's plastic state, which the
    // stepper iterates on.
    if (parameters.strength.plasticity == GradedStrength::Plasticity::j2)
      {
        strength   = std::make_unique<GradedStrength>(parameters.strength,
                                                    plate.get_material());
        plasticity = std::make_unique<PlasticPlate>(plate, *strength);
        if (thermal_state) // plasticity from the thermal pre-stress
          {
            plasticity->set_prestress(thermal_state->initial_stress());
            plasticity->refuse_yielding_prestress();
          }
        stepper->set_plasticity(*plasticity,
                                parameters.time_integration.newton.tolerance);
      }
  }



  double
  ImpactDriver::hertz_contact_duration() const
  {
    return hertz_impact_duration(contact_law.force(1.),
                                 impactor.mass(),
                                 impactor.initial_velocity());
  }



  std::string
  ImpactDriver::blow_up_advice() const
  {
    // The remedy for this scheme: a run already on the average
    // acceleration rule was told to use it (Impactor/Radius = 1e-6 with
    // dt = 2 us: Hertz's contact lasts 0.008 us).
    const auto  &ti = parameters.time_integration;
    const double T  = hertz_contact_duration();
    char         text[400];
    if (ti.scheme == TimeStepper::Scheme::central_difference)
      return "lower Time integration/Stable step safety factor, or use "
             "Time integration/Scheme = implicit";
    std::snprintf(text,
                  sizeof(text),
                  "reduce Time integration/Time step: Hertz's contact lasts "
                  "about %.3g us, which %.3g us steps resolve with %.3g "
                  "steps (use at most %.3g us)%s",
                  T * 1e6,
                  dt * 1e6,
                  T / dt,
                  T / 20. * 1e6,
                  ti.newmark.beta == 0.25 && ti.newmark.gamma == 0.5 ?
                    "" :
                    ", or use Newmark beta = 0.25, gamma = 0.5");
    return text;
  }



  void
  ImpactDriver::check_time_step() const
  {
    // The automatic explicit step is known only now (a given step is
    // checked with the parameters).
    AssertThrow(parameters.time_integration.end_time >= dt * (1. - 1e-9),
                ExcMessage(
                  std::string("Time integration/") +
                  (parameters.time_integration.auto_end_time ?
                     "Maximum end time = " :
                     "End time = ") +
                  std::to_string(parameters.time_integration.end_time * 1e6) +
                  " us is shorter than one time step (" +
                  std::to_string(dt * 1e6) + " us)."));
    // Can dt resolve the contact?  Fewer than 20 steps in Hertz's duration
    // is a coarse time history.
    const double T_hertz = hertz_contact_duration();
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
  ImpactDriver::note_contact_resolution()
  {
    const ModelDescription &d = results.model;
    const double            h = d.element_size_under_ball;
    char                    text[600];
    if (parameters.contact_model.model ==
        ContactModelParameters::Model::hertz_node)
      {
        // The paper's point force: u ~ 1/r under it, so the force depends
        // on the mesh (README, doc/contact.md).
        std::snprintf(text,
                      sizeof(text),
                      "  note: Contact/Model = hertz node puts the contact "
                      "force on one node: the peak force depends on the "
                      "element size under the ball (%.4g mm here) and does "
                      "not converge under refinement; "
                      "scripts/contact_convergence.sh FILE.prm measures its "
                      "error for this scene against the resolved sphere.\n",
                      h * 1e3);
        pcout << text;
        return;
      }
    const double a_max = scene.expected_contact_radius();
    if (parameters.contact_model.model ==
          ContactModelParameters::Model::resolved_sphere &&
        a_max < contact_elements_per_radius * h)
      {
        std::snprintf(text,
                      sizeof(text),
                      "  WARNING: the estimated largest contact radius "
                      "(%.4g mm, Hertz on a half-space) spans %.2f element "
                      "sizes (%.4g mm), fewer than %.0f: the resolved "
                      "contact force will not be accurate; raise "
                      "Geometry/Contact refinement levels (now %u) or set "
                      "it to auto.\n",
                      a_max * 1e3,
                      a_max / h,
                      h * 1e3,
                      contact_elements_per_radius,
                      d.contact_refinement_levels);
        pcout << text;
      }
  }
  namespace
  {
    /// Accumulates the plate's refinement indicator (the pilot run of an
    /// adaptive mesh) every `stride` steps: eta^2 times stride dt, the
    /// rectangle rule of its time integral.  Kelly's estimate costs more
    /// than a time step (default scene's second pilot, 25,000 DoFs: about
    /// 55 ms against 22 ms; 16.4 s for the run at every step, 5.2 s at
    /// this stride, with the same cells refined), so it samples the
    /// contact some 16 times rather than at every step.
    class IndicatorRecorder : public Postprocessor
    {
    public:
      IndicatorRecorder(RefinementIndicator &indicator,
                        const double         dt,
                        const unsigned int   stride)
        : indicator(indicator)
        , dt(dt)
        , stride(stride)
      {}

      void
      execute(const StepRecord &record) override
      {
        if (record.step > 0 && record.step % stride == 0 && record.fields)
          indicator.add(record.fields->displacement(), stride * dt);
      }

    private:
      RefinementIndicator &indicator;
      const double         dt; // s
      const unsigned int   stride;
    };
  } // namespace



  void
  ImpactDriver::add_refinement_indicator()
  {
    if (refinement_indicator)
      monitor->add(std::make_unique<IndicatorRecorder>(
        *refinement_indicator,
        dt,
        std::max(1u,
                 static_cast<unsigned int>(hertz_contact_duration() /
                                           (16. * dt)))));
  }
} // namespace fgimpact
