#include <deal.II/base/mpi.h>

#include <deal.II/lac/lapack_full_matrix.h>

#include <fgimpact/analysis/impact_setup.h>
#include <fgimpact/base/exceptions.h>
#include <fgimpact/base/stop_signals.h>
#include <fgimpact/contact/contact_law.h>
#include <fgimpact/contact/contact_model.h>
#include <fgimpact/contact/impactor.h>
#include <fgimpact/output/impact_summary.h>
#include <fgimpact/output/validity_report.h>
#include <fgimpact/plate/probes.h>
#include <fgimpact/study/impact_study_engine.h>
#include <fgimpact/study/simulator.h>
#include <fgimpact/time/contact_coupler.h>
#include <fgimpact/time/newmark.h>
#include <fgimpact/time/plate_fields.h>
#include <fgimpact/time/time_stepper.h>

#include <cmath>
#include <sstream>

namespace fgimpact
{
  namespace
  {
    /// A stop signal (SIGINT, SIGTERM, SIGHUP, SIGXFSZ: it only set a
    /// flag) since the last look: its number, agreed over the ranks.
    int
    stop_requested(const PlateModel &plate)
    {
      return agreed_stop(plate.get_mpi_communicator(), false);
    }

    /// A case's contact model, built as ImpactDriver::setup() builds it.
    std::unique_ptr<ContactModel>
    contact_model_of(const Parameters      &p,
                     const HertzContactLaw &law,
                     const Scene           &scene,
                     const PlateModel      &plate)
    {
      return create_contact_model(p.contact_model,
                                  law,
                                  plate,
                                  scene.impactor().radius(),
                                  scene.impact_point_in_plane(),
                                  scene.expected_contact_radius(),
                                  scene.top_face_modulus(),
                                  scene.impactor().indentation_modulus());
    }


    /**
     * The plate as the convolution of its unit response (a PlateResponse
     * for the ContactCoupler): the contact DoF's contact-free displacement
     * at step n + 1 is sum_{k <= n} F_k r_{n+2-k} (what the stepper would
     * solve for), the probes and the kinetic energy likewise; the strain
     * energy is the contact force's work (trapezoidal, exact for average
     * acceleration) minus the kinetic energy.
     */
    class ConvolutionResponse : public PlateResponse
    {
    public:
      /// Unit responses, index j - 1 for step j: the contact DoF's
      /// displacement (m, positive up), the probes; gram: G_ij = v_i^T M v_j.
      ConvolutionResponse(const double                    dt,
                          const double                    compliance,
                          const std::vector<double>      &contact_response,
                          const std::vector<PlateSample> &probe_response,
                          const FullMatrix<double>       &gram)
        : dt(dt)
        , C(1, 1)
        , contact_response(contact_response)
        , probe_response(probe_response)
        , gram(gram)
        , F(contact_response.size() + 1, 0.)
      {
        C(0, 0) = compliance;
      }

      double
      time_step() const override
      {
        return dt;
      }

      Vector<double>
      predict(const unsigned int step,
              const double,
              const ContactState &) override
      {
        // The response to the forces of the steps before.
        Vector<double> u_free(1);
        for (unsigned int k = 1; k < step; ++k)
          u_free[0] += F[k] * contact_response[step - k];
        return u_free;
      }

      const FullMatrix<double> &
      compliance() const override
      {
        return C;
      }

      bool
      correct(const unsigned int step,
              const double,
              const ContactState &contact) override
      {
        F[step] = contact.force;
        sample  = convolved_plate(step);
        // The plate's energy grows by the contact force's work on the
        // contact DoF (average acceleration: exactly, per step).
        plate_energy +=
          0.5 * (F[step - 1] + F[step]) * (last_uc - contact.node_displacement);
        last_uc         = contact.node_displacement;
        sample.E_strain = plate_energy - sample.E_kinetic;
        return true;
      }

      double
      kinetic_energy() const override
      {
        return sample.E_kinetic;
      }

      double
      strain_energy() const override
      {
        return sample.E_strain;
      }

      /// The history's probes and energies after the last step.
      const PlateSample &
      plate_sample() const
      {
        return sample;
      }

    private:
      /// Step n (F[1..n] known): sum_k F_k r_{n-k} over the forces so far.
      PlateSample
      convolved_plate(const unsigned int n) const
      {
        PlateSample s;
        double      sigma[6] = {0, 0, 0, 0, 0, 0};
        for (unsigned int k = 1; k <= n; ++k)
          if (F[k] != 0.)
            {
              const PlateSample &r = probe_response[n - k];
              s.W_mid += F[k] * r.W_mid;
              s.W_top += F[k] * r.W_top;
              for (unsigned int c = 0; c < 6; ++c)
                sigma[c] += F[k] * r.sigma_mid.access_raw_entry(c);
            }
        for (unsigned int c = 0; c < 6; ++c)
          s.sigma_mid.access_raw_entry(c) = sigma[c];
        // Kinetic energy 1/2 v^T M v with v = sum_k F_k v_{n-k}: the
        // quadratic form of G over the steps with a force (symmetric: half
        // of it).
        double kinetic = 0;
        for (unsigned int k = 1; k <= n; ++k)
          if (F[k] != 0.)
            {
              double row = 0.5 * gram(n - k, n - k) * F[k];
              for (unsigned int l = 1; l < k; ++l)
                row += gram(n - k, n - l) * F[l];
              kinetic += F[k] * row;
            }
        s.E_kinetic = kinetic;
        return s;
      }

      const double                    dt;
      FullMatrix<double>              C; // m/N
      const std::vector<double>      &contact_response;
      const std::vector<PlateSample> &probe_response;
      const FullMatrix<double>       &gram;
      std::vector<double>             F; // N, index: step
      PlateSample                     sample;
      double                          plate_energy = 0, last_uc = 0;
    };
  } // namespace



  ImpactStudyEngine::ImpactStudyEngine(const PlateModel &plate,
                                       const Timer      &total_timer)
    : plate(plate)
    , total_timer(total_timer)
    , pcout(std::cout,
            Utilities::MPI::this_mpi_process(plate.get_mpi_communicator()) == 0)
  {}



  std::string
  ImpactStudyEngine::unsupported(const Parameters &p,
                                 const PlateModel &plate,
                                 const double      memory_limit)
  {
    const auto &ti = p.time_integration;
    if (p.problem_type != ProblemType::impact)
      return "Problem type is not impact";
    if (p.contact_model.model != ContactModelParameters::Model::hertz_node)
      return "Contact/Model is not hertz node";
    if (ti.auto_end_time)
      return "Time integration/End time = auto (the convolution needs a "
             "fixed time span)";
    if (ti.scheme != TimeStepper::Scheme::implicit_newmark)
      return "Time integration/Scheme is not implicit";
    if (ti.newmark.beta != 0.25 || ti.newmark.gamma != 0.5)
      return "Newmark beta/gamma are not 1/4, 1/2 (the energy identity "
             "holds for the average acceleration rule only)";
    if (p.output.vtu_interval > 0)
      return "Output/VTU interval > 0 (VTU needs the fields)";
    // The unit responses are the bare plate's: neither the thermal state's
    // stress nor its geometric stiffness (issue 42).
    if (p.thermal.active())
      return "Thermal/Temperature field is set (the unit responses know "
             "neither the thermal pre-stress nor its stiffness)";
    const double bytes =
      16. * ti.n_steps(ti.time_step) * plate.locally_owned_dofs().n_elements();
    if (bytes > memory_limit)
      return "the unit responses would need " +
             std::to_string(static_cast<long long>(bytes / 1e6)) +
             " MB per rank";
    return "";
  }



  bool
  ImpactStudyEngine::record_unit_response(TimeStepper              &stepper,
                                          LAPACKFullMatrix<double> &V,
                                          LAPACKFullMatrix<double> &MV)
  {
    const PlateGeometry &g = plate.get_geometry();
    // The history's probes, as the monitor places them.
    const auto       points = history_probe_points(g);
    const PointProbe mid(plate, points[0]), top(plate, points[1]);
    // The probes read the unit response with the constraints distributed
    // (a probe on a hanging node reads its parents' interpolation).
    PlateFields fields(plate);
    contact_response.assign(n_steps, 0.);
    probe_response.assign(n_steps, PlateSample());
    const std::size_t n_local = plate.locally_owned_dofs().n_elements();
    return stepper.unit_response(
      n_steps,
      [&](const unsigned int                   j,
          const TrilinosWrappers::MPI::Vector &u,
          const TrilinosWrappers::MPI::Vector &v,
          const TrilinosWrappers::MPI::Vector &Mv) {
        // The message is built only if a signal came.
        if (const int stop = stop_requested(plate); stop > 0)
          throw RunInterrupted(stop,
                               std::string("interrupted by ") +
                                 signal_name(stop) +
                                 " while the convolution study was being "
                                 "prepared (unit response step " +
                                 std::to_string(j) + " of " +
                                 std::to_string(n_steps) +
                                 "): no case computed; run the study again.");
        contact_response[j - 1] = plate.dof_values(u, dofs)[0];
        fields.update_displacement(u);
        probe_response[j - 1] = probe_plate(mid, top, fields.displacement());
        for (std::size_t i = 0; i < n_local; ++i)
          {
            V(i, j - 1)  = v.begin()[i];
            MV(i, j - 1) = Mv.begin()[i];
          }
      });
  }



  void
  ImpactStudyEngine::compute_gram(const LAPACKFullMatrix<double> &V,
                                  const LAPACKFullMatrix<double> &MV)
  {
    LAPACKFullMatrix<double> G(n_steps, n_steps);
    V.Tmmult(G, MV);
    gram.reinit(n_steps, n_steps);
    for (unsigned int i = 0; i < n_steps; ++i)
      for (unsigned int j = 0; j < n_steps; ++j)
        gram(i, j) = G(i, j);
    Utilities::MPI::sum(gram, plate.get_mpi_communicator(), gram);
  }



  bool
  ImpactStudyEngine::prepare(const Parameters &p)
  {
    setup_time = total_timer.wall_time();
    Timer       timer;
    const Scene scene(p, plate.get_material(), plate.get_geometry().share());
    const Impactor       &impactor = scene.impactor();
    const HertzContactLaw law(p.contact, plate.get_material(), impactor);
    const auto            contact = contact_model_of(p, law, scene, plate);
    dofs                          = contact->contact_dofs();
    const auto stepper            = create_time_stepper(p.time_integration,
                                             p.linear_solver,
                                             plate,
                                             *contact,
                                             scene.share() * impactor.mass(),
                                             impactor.initial_velocity());
    stepper->initialize(false);
    factorization_time = timer.wall_time();
    dt                 = stepper->time_step();
    n_steps            = p.time_integration.n_steps(dt);

    // Column j - 1: the step's local velocity values (contiguous).
    const std::size_t        n_local = plate.locally_owned_dofs().n_elements();
    LAPACKFullMatrix<double> V(n_local, n_steps), MV(n_local, n_steps);
    if (!record_unit_response(*stepper, V, MV))
      {
        reason = "the time stepper has no unit response here (an iterative "
                 "linear solver: set Linear solver/Type = auto or cholmod)";
        return false;
      }
    compliance    = -contact_response[0];
    response_time = timer.wall_time() - factorization_time;

    compute_gram(V, MV);
    prepare_time = timer.wall_time();
    gram_time    = prepare_time - response_time - factorization_time;
    return true;
  }



  void
  ImpactStudyEngine::stop_case(ImpactMonitor       &monitor,
                               const ImpactorState &ball,
                               const unsigned int   steps_done,
                               const int            stop,
                               const double         loop_time) const
  {
    // The case's files end at the last step done, as an interrupted run's.
    monitor.close_output();
    monitor.finish(
      ball, steps_done, "interrupted", loop_time, total_timer.wall_time());
    throw RunInterrupted(
      stop,
      std::string("interrupted by ") + signal_name(stop) + " after time step " +
        std::to_string(steps_done) + " of " + std::to_string(n_steps) +
        " of a convolution study case; its history.csv and summary.txt "
        "(status = interrupted) are complete up to there and the cases "
        "before it are whole; convolution cases keep no checkpoint (they "
        "are cheap): run the study again.");
  }



  std::string
  ImpactStudyEngine::preparation_timing() const
  {
    std::ostringstream s;
    s << "factorization " << factorization_time << " s, unit response pass "
      << response_time << " s (" << n_steps << " solves), Gram matrix "
      << gram_time << " s";
    return s.str();
  }



  void
  ImpactStudyEngine::start_results(const Parameters   &p,
                                   const Scene        &scene,
                                   const ContactModel &contact)
  {
    results = setup_results(plate, scene, contact, setup_time);
    results.factorization_time = factorization_time;
    results.model              = describe_model(p, scene, plate, dt);
  }



  void
  ImpactStudyEngine::check_case(const Parameters   &p,
                                const ContactModel &contact) const
  {
    AssertThrow(contact.contact_dofs() == dofs,
                ExcMessage("study: a case's contact node differs from the "
                           "group's; vary Impactor/Impact point x/y only in "
                           "separate runs."));
    AssertThrow(p.time_integration.n_steps(dt) == n_steps,
                ExcMessage("study: a case's number of time steps differs "
                           "from the group's."));
  }



  std::unique_ptr<ImpactMonitor>
  ImpactStudyEngine::start_monitor(const Parameters   &p,
                                   const Scene        &scene,
                                   const ContactModel &contact,
                                   SummaryFile        &summary)
  {
    const Impactor &impactor = scene.impactor();
    // No probes.csv: its probes need the fields (--study-case K writes it).
    OutputParameters output = p.output;
    output.probe_points.points.clear();
    auto monitor = std::make_unique<ImpactMonitor>(output,
                                                   plate,
                                                   contact,
                                                   impactor.mass(),
                                                   impactor.initial_velocity(),
                                                   dt,
                                                   n_steps,
                                                   results,
                                                   summary);
    for (const auto &observer : observers)
      monitor->add_row_observer(observer);
    // Without fields: Hertz's closed form and the rigid ball only.
    monitor->add(std::make_unique<ValidityMonitor>(
      plate, validity_setup(p, scene, contact, results), results, pcout));
    monitor->start();
    return monitor;
  }



  const ImpactResults &
  ImpactStudyEngine::run_case(const Parameters &p, SummaryFile &summary)
  {
    const Scene scene(p, plate.get_material(), plate.get_geometry().share());
    const Impactor       &impactor = scene.impactor();
    const HertzContactLaw law(p.contact, plate.get_material(), impactor);
    const auto            contact = contact_model_of(p, law, scene, plate);
    check_case(p, *contact);
    const double m = impactor.mass(), V0 = impactor.initial_velocity();
    // A symmetric part (Geometry/Symmetry): the part's share of the ball's
    // mass meets the part's share of the contact force, as in ImpactDriver;
    // the monitor reports the whole plate.
    const double m_part = scene.share() * m;

    start_results(p, scene, *contact);

    const auto    monitor = start_monitor(p, scene, *contact, summary);
    ImpactorState ball;
    ball.v = V0;
    ContactState state;
    monitor->record(0, 0., PlateSample(), ball, state);

    ConvolutionResponse response(
      dt, compliance, contact_response, probe_response, gram);
    ContactCoupler coupler(response,
                           *contact,
                           p.time_integration.newmark,
                           m_part,
                           p.time_integration.newton,
                           plate.get_mpi_communicator());
    Timer          loop_timer;
    for (unsigned int n = 0; n < n_steps; ++n)
      {
        if (const int stop = stop_requested(plate); stop > 0)
          stop_case(*monitor, ball, n, stop, loop_timer.wall_time());
        const double t = (n + 1) * dt;
        coupler.advance(n + 1, t, ball, state);
        monitor->record(n + 1, t, response.plate_sample(), ball, state);
      }
    monitor->close_output();
    // A failed write on any rank (rank 0 writes history.csv): every rank
    // agrees and throws the failing rank's message, so none is left
    // waiting in the next collective call.
    const std::string failure = monitor->agreed_output_failure();
    AssertThrow(failure.empty(), ExcOutputFailure(failure));
    monitor->finish(ball,
                    n_steps,
                    "completed",
                    loop_timer.wall_time(),
                    total_timer.wall_time());
    return results;
  }
} // namespace fgimpact
