#include <deal.II/base/timer.h>

#include <fgimpact/modal_analysis.h>
#include <fgimpact/postprocessing.h>
#include <fgimpact/probes.h>
#include <fgimpact/simulator.h>
#include <fgimpact/static_analysis.h>
#include <fgimpact/time_stepper.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>

namespace fgimpact
{
  void
  ImpactSimulator::Parameters::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Problem type",
                      "impact",
                      Patterns::Selection("impact|static|modal"),
                      "impact: the sphere strikes the plate (time history). "
                      "static: K u = f under the load of subsection Static. "
                      "modal: the lowest natural frequencies and mode "
                      "shapes (subsection Modal).");
    AccuracyPreset::Parameters::declare_parameters(prm);
    PlateGeometry::Parameters::declare_parameters(prm);
    StaticAnalysis::Parameters::declare_parameters(prm);
    ModalAnalysis::Parameters::declare_parameters(prm);
    FunctionallyGradedMaterial::Parameters::declare_parameters(prm);
    HertzContactLaw::Parameters::declare_parameters(prm);
    Impactor::Parameters::declare_parameters(prm);
    NewmarkIntegrator::Parameters::declare_parameters(prm);
    PlateModel::Parameters::declare_parameters(prm);
    EffectiveMatrixSolver::Parameters::declare_parameters(prm);

    TimeStepper::Parameters::declare_parameters(prm);

    prm.enter_subsection("Output");
    {
      prm.declare_entry("Directory",
                        "output",
                        Patterns::DirectoryName(),
                        "Directory for history.csv, summary.txt, "
                        "parameters.prm and the VTU/PVD files; created if "
                        "missing.");
      prm.declare_entry("VTU interval",
                        "0",
                        Patterns::Integer(0, 100000000),
                        "Write VTU every this many time steps (and the "
                        "initial state); 0 = no VTU output.");
      prm.declare_entry("Log interval",
                        "50",
                        Patterns::Integer(0, 100000000),
                        "Print a progress line every this many steps; 0 = "
                        "none.");
      prm.declare_entry("Print timing",
                        "true",
                        Patterns::Bool(),
                        "Print the wall-clock timing table at the end (turn "
                        "off for reproducible logs).");
    }
    prm.leave_subsection();
  }



  void
  ImpactSimulator::Parameters::parse_parameters(ParameterHandler &prm)
  {
    problem_type = prm.get("Problem type");
    // First: a preset rewrites the Geometry and Time integration entries
    // in prm that the calls below read.
    accuracy.parse_parameters(prm);
    static_analysis.parse_parameters(prm);
    modal.parse_parameters(prm);
    geometry.parse_parameters(prm);
    material.parse_parameters(prm);
    contact.parse_parameters(prm);
    impactor.parse_parameters(prm);
    time_integration.parse_parameters(prm);
    finite_element.parse_parameters(prm);
    linear_solver.parse_parameters(prm);

    time_stepper.parse_parameters(prm);

    prm.enter_subsection("Output");
    output_directory = prm.get("Directory");
    vtu_interval     = prm.get_integer("VTU interval");
    log_interval     = prm.get_integer("Log interval");
    print_timing     = prm.get_bool("Print timing");
    prm.leave_subsection();
  }



  void
  ImpactSimulator::Parameters::validate() const
  {
    const double   a = geometry.length, b = geometry.width;
    const Impactor impactor_object(impactor);
    const Point<2> p = impactor_object.impact_point(a, b);
    AssertThrow(p[0] > 0 && p[0] < a,
                ExcMessage("Impactor/Impact point x = " + std::to_string(p[0]) +
                           " m lies outside the open interval (0, a = " +
                           std::to_string(a) + " m)."));
    AssertThrow(p[1] > 0 && p[1] < b,
                ExcMessage("Impactor/Impact point y = " + std::to_string(p[1]) +
                           " m lies outside the open interval (0, b = " +
                           std::to_string(b) + " m)."));
    AssertThrow(time_integration.time_step > 0 || time_stepper.explicit_scheme,
                ExcMessage("Time integration/Time step = 0 (automatic) is "
                           "only available with Scheme = explicit."));
    AssertThrow(time_integration.end_time >= time_integration.time_step,
                ExcMessage("Time integration/End time is shorter than one "
                           "Time step."));
    AssertThrow(time_integration.time_step == 0 ||
                  time_integration.end_time / time_integration.time_step < 1e8,
                ExcMessage("Time integration/End time divided by Time step "
                           "exceeds 1e8 steps."));
    AssertThrow(time_stepper.explicit_scheme ||
                  time_integration.beta >= time_integration.gamma / 4. - 1e-14,
                ExcMessage("Time integration/Newmark beta must be at least "
                           "gamma/4 for the unconditionally stable implicit "
                           "scheme (beta = 1/4, gamma = 1/2 is the default)."));
    AssertThrow(output_directory.find_first_not_of(" \t") != std::string::npos,
                ExcMessage("Output/Directory is empty."));
  }



  ImpactSimulator::ImpactSimulator(const Parameters &parameters,
                                   const MPI_Comm    mpi_communicator)
    : parameters(parameters)
    , mpi_communicator(mpi_communicator)
    , pcout(std::cout, Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
  {}



  void
  ImpactSimulator::setup()
  {
    total_timer.restart();
    Timer setup_timer;
    geometry_ptr = std::make_unique<PlateGeometry>(parameters.geometry);
    const PlateGeometry &geometry = *geometry_ptr;
    material_ptr =
      std::make_unique<FunctionallyGradedMaterial>(parameters.material,
                                                   geometry.thickness());
    const FunctionallyGradedMaterial &material = *material_ptr;
    impactor_ptr             = std::make_unique<Impactor>(parameters.impactor);
    const Impactor &impactor = *impactor_ptr;
    contact_law_ptr =
      std::make_unique<HertzContactLaw>(parameters.contact, material, impactor);
    const HertzContactLaw &contact_law = *contact_law_ptr;

    plate_ptr         = std::make_unique<PlateModel>(parameters.finite_element,
                                             geometry,
                                             material,
                                             mpi_communicator);
    PlateModel &plate = *plate_ptr;
    plate.setup();

    const double m_i = impactor.mass();
    const double V0  = impactor.initial_velocity();

    results.n_dofs            = plate.n_dofs();
    results.impactor_mass     = m_i;
    results.plate_mass        = plate.total_mass();
    results.contact_modulus   = contact_law.contact_modulus();
    results.contact_stiffness = contact_law.force(1.); // beta K_h

    const auto [dof, contact_node] = plate.nearest_top_vertex_dof(
      impactor.impact_point(geometry.length(), geometry.width()), 2);
    contact_dof = dof;
    // Only the owner knows for sure whether the DoF is constrained.
    const bool contact_dof_constrained =
      Utilities::MPI::max((plate.locally_owned_dofs().is_element(contact_dof) &&
                           plate.get_constraints().is_constrained(
                             contact_dof)) ?
                            1u :
                            0u,
                          mpi_communicator) == 1u;
    results.contact_node_owner = plate.dof_owner(contact_dof);
    results.n_mpi_ranks = Utilities::MPI::n_mpi_processes(mpi_communicator);
    AssertThrow(parameters.problem_type != "impact" || !contact_dof_constrained,
                ExcMessage("Impactor/Impact point: the nearest top-surface "
                           "node lies on a supported face; move the impact "
                           "point inside the plate."));

    const Point<2> impact_point =
      impactor.impact_point(geometry.length(), geometry.width());
    const double node_offset =
      Point<2>(contact_node[0], contact_node[1]).distance(impact_point);
    results.contact_node_offset = node_offset;

    mid_probe =
      std::make_unique<PointProbe>(plate,
                                   geometry.centre(geometry.thickness() / 2));
    top_probe =
      std::make_unique<PointProbe>(plate,
                                   geometry.centre(geometry.thickness()));

    pcout << "fgimpact: FGM plate " << geometry.length() << " x "
          << geometry.width() << " x " << geometry.thickness() << " m, "
          << plate.n_active_cells() << " cells, " << plate.n_dofs()
          << " DoFs (Q" << plate.get_fe().degree << ", "
          << (parameters.material.property_mode == PropertyMode::graded ?
                "graded" :
              parameters.material.property_mode == PropertyMode::homogeneous ?
                "homogeneous" :
                "pointwise")
          << " elements), n = " << parameters.material.power_law_index << '\n'
          << "  impactor mass " << m_i << " kg, V0 = " << V0
          << " m/s; Q_alpha = " << contact_law.contact_modulus() / 1e9
          << " GPa, beta K_h = " << results.contact_stiffness << " N/m^1.5\n"
          << "  contact node (" << contact_node[0] << ", " << contact_node[1]
          << ", " << contact_node[2] << ") m, owned by MPI rank "
          << results.contact_node_owner << '\n';
    {
      const unsigned int n_ranks = results.n_mpi_ranks;
      const auto         owned =
        Utilities::MPI::min_max_avg(static_cast<double>(
                                      plate.locally_owned_dofs().n_elements()),
                                    mpi_communicator);
      pcout << "  " << n_ranks << " MPI rank" << (n_ranks > 1 ? "s" : "")
            << ", DoFs per rank min "
            << static_cast<types::global_dof_index>(owned.min) << " / max "
            << static_cast<types::global_dof_index>(owned.max) << '\n';
    }
    if (!parameters.accuracy.log_message.empty())
      pcout << "  " << parameters.accuracy.log_message << '\n';

    if (node_offset > 1e-9 * geometry.length())
      pcout << "  note: no node lies at the impact point; the contact force "
               "acts at the nearest top node, "
            << node_offset * 1e3 << " mm away (choose Subdivisions so that "
            << "a node lies under the impact point)\n";

    results.setup_time = setup_timer.wall_time();
    if (parameters.problem_type != "impact")
      return;

    // The time stepper (implicit Newmark or explicit central difference)
    // builds its matrices and fixes the time step.
    Timer factorization_timer;
    stepper = create_time_stepper(parameters.time_stepper,
                                  parameters.time_integration,
                                  parameters.linear_solver,
                                  plate,
                                  contact_law,
                                  contact_dof,
                                  m_i,
                                  V0);
    stepper->initialize();
    results.factorization_time = factorization_timer.wall_time();
    results.spmv_time          = stepper->spmv_time;
    results.solve_time         = stepper->solve_time;

    dt = stepper->time_step();
    n_steps =
      NewmarkIntegrator::number_of_steps(parameters.time_integration.end_time,
                                         dt);
    pcout << "  " << stepper->description() << "; dt = " << dt * 1e6 << " us, "
          << n_steps << " steps\n";
  }



  void
  ImpactSimulator::run()
  {
    if (!plate_ptr)
      setup();
    if (parameters.problem_type == "static")
      run_static();
    else if (parameters.problem_type == "modal")
      run_modal();
    else
      run_impact();
  }



  void
  ImpactSimulator::run_static()
  {
    StaticAnalysis analysis(parameters.static_analysis,
                            parameters.linear_solver,
                            *plate_ptr,
                            impactor_ptr->impact_point(geometry_ptr->length(),
                                                       geometry_ptr->width()));
    analysis.solve();
    analysis.write_output(parameters.output_directory);
    const auto &r = analysis.get_results();
    char        line[300];
    std::snprintf(line,
                  sizeof(line),
                  "  static deflection at the centre: bottom %.6f um, mid "
                  "%.6f um, top %.6f um\n"
                  "  sigma_xx at the centre: bottom %.4f MPa, mid %.4f MPa, "
                  "top %.4f MPa\n",
                  r.deflection[0] * 1e6,
                  r.deflection[1] * 1e6,
                  r.deflection[2] * 1e6,
                  r.sigma_xx[0] * 1e-6,
                  r.sigma_xx[1] * 1e-6,
                  r.sigma_xx[2] * 1e-6);
    pcout << line;
  }



  void
  ImpactSimulator::run_modal()
  {
    ModalAnalysis analysis(parameters.modal,
                           parameters.linear_solver,
                           *plate_ptr);
    analysis.solve();
    analysis.write_output(parameters.output_directory);
    pcout << "  " << analysis.get_modes().size() << " modes after "
          << analysis.n_iterations() << " subspace iterations:\n";
    for (unsigned int j = 0; j < analysis.get_modes().size(); ++j)
      {
        char line[120];
        std::snprintf(line,
                      sizeof(line),
                      "  mode %2u  %12.4f Hz  w-energy fraction %.3f\n",
                      j + 1,
                      analysis.get_modes()[j].frequency,
                      analysis.get_modes()[j].w_fraction);
        pcout << line;
      }
  }



  void
  ImpactSimulator::run_impact()
  {
    const Impactor        &impactor    = *impactor_ptr;
    const HertzContactLaw &contact_law = *contact_law_ptr;
    const PlateModel      &plate       = *plate_ptr;
    const double           m_i         = impactor.mass();
    const double           V0          = impactor.initial_velocity();
    // Plain timers (not TimerOutput, whose destructor writes to the screen
    // when an exception such as a Newton failure is on its way out).
    Timer loop_timer, output_timer;
    output_timer.stop();
    output_timer.reset();

    // ------------------------------------------------------- time stepping
    // Impactor state, positive in the impact direction (-z).  Eq. 2.16:
    // plate at rest, alpha(0) = 0, alpha'(0) = V0; a(0) = 0 as F(0) = 0.
    ImpactorState ball;
    ball.v = V0;
    ContactState contact;

    const double E0 = 0.5 * m_i * V0 * V0;

    history_rows.clear();
    history_rows.reserve(n_steps + 1); // no reallocation in the time loop
    std::unique_ptr<CsvWriter> history;
    std::unique_ptr<VtuWriter> vtu;
    const bool root = Utilities::MPI::this_mpi_process(mpi_communicator) == 0;
    if (root)
      history =
        std::make_unique<CsvWriter>(parameters.output_directory +
                                      "/history.csv",
                                    std::vector<std::pair<std::string, int>>{
                                      {"t_us", 4},
                                      {"contact_force_N", 4},
                                      {"indentation_um", 5},
                                      {"impactor_displacement_um", 5},
                                      {"impactor_velocity_m_s", 7},
                                      {"midplane_deflection_um", 5},
                                      {"top_deflection_um", 5},
                                      {"sigma_xx_mid_MPa", 5},
                                      {"sigma_yy_mid_MPa", 5},
                                      {"sigma_zz_mid_MPa", 5},
                                      {"energy_impactor_J", 9},
                                      {"energy_plate_kinetic_J", 9},
                                      {"energy_strain_J", 9},
                                      {"energy_contact_J", 9},
                                      {"energy_total_J", 9},
                                      {"contact_node_deflection_um", 5},
                                      {"newton_iterations", 0}});
    if (parameters.vtu_interval > 0)
      vtu = std::make_unique<VtuWriter>(plate, parameters.output_directory);

    // Time history bookkeeping.
    bool         in_contact      = true; // alpha(0) = 0 with alpha' > 0
    bool         separated_once  = false;
    double       separation_time = std::numeric_limits<double>::quiet_NaN();
    double       impulse         = 0;
    unsigned int n_impacts       = 1;

    double last_force = 0, peak_left = 0;
    bool   peak_pending = false;
    auto   record       = [&](const unsigned int step, const double t) {
      const auto                 &u       = stepper->displacement();
      const Tensor<1, 3>          u_mid   = mid_probe->displacement(u);
      const Tensor<1, 3>          u_top   = top_probe->displacement(u);
      const SymmetricTensor<2, 3> sigma   = mid_probe->stress(u);
      const double                W_mid   = -u_mid[2];
      const double                W_top   = -u_top[2];
      const double                W_c     = -contact.node_displacement;
      const double                F       = contact.force;
      const double                alpha   = contact.alpha;
      const double                E_imp   = 0.5 * m_i * ball.v * ball.v;
      const double                E_kin   = stepper->kinetic_energy();
      const double                E_str   = stepper->strain_energy();
      const double                E_con   = contact_law.potential(alpha);
      const double                E_total = E_imp + E_kin + E_str + E_con;

      results.max_energy_drift =
        std::max(results.max_energy_drift, std::abs(E_total - E0) / E0);
      // Peak force: the parabola through the largest sample and its two
      // neighbours (second-order accurate in dt, unlike the largest sample,
      // whose error depends on where the samples fall).
      if (F > results.max_sampled_force)
        {
          results.max_sampled_force  = F;
          results.peak_contact_force = F;
          results.time_of_peak_force = t;
          peak_left                  = last_force;
          peak_pending               = true;
        }
      else if (peak_pending)
        {
          const double Fm = results.max_sampled_force;
          const double d  = peak_left - 2. * Fm + F;
          if (d < 0.)
            {
              results.peak_contact_force =
                Fm - (peak_left - F) * (peak_left - F) / (8. * d);
              results.time_of_peak_force =
                t - dt + dt * (peak_left - F) / (2. * d);
            }
          peak_pending = false;
        }
      last_force              = F;
      results.max_indentation = std::max(results.max_indentation, alpha);
      results.max_midplane_deflection =
        std::max(results.max_midplane_deflection, W_mid);
      results.max_top_deflection = std::max(results.max_top_deflection, W_top);
      results.max_newton_iterations =
        std::max(results.max_newton_iterations, contact.newton_iterations);

      history_rows.push_back({t * 1e6,
                              F,
                              alpha * 1e6,
                              ball.w * 1e6,
                              ball.v,
                              W_mid * 1e6,
                              W_top * 1e6,
                              sigma[0][0] * 1e-6,
                              sigma[1][1] * 1e-6,
                              sigma[2][2] * 1e-6,
                              E_imp,
                              E_kin,
                              E_str,
                              E_con,
                              E_total,
                              W_c * 1e6,
                              static_cast<double>(contact.newton_iterations)});
      if (history)
        history->write_row(history_rows.back());
      if (vtu && step % parameters.vtu_interval == 0)
        {
          output_timer.start();
          vtu->write(step, t, u, stepper->velocity());
          output_timer.stop();
        }
      if (parameters.log_interval > 0 &&
          (step % parameters.log_interval == 0 || step == n_steps))
        {
          char line[200];
          std::snprintf(line,
                        sizeof(line),
                        "  step %6u  t = %9.3f us  F = %10.3f N  alpha = "
                                "%8.4f um  W_mid = %8.4f um  E/E0 - 1 = %+.2e\n",
                        step,
                        t * 1e6,
                        F,
                        alpha * 1e6,
                        W_mid * 1e6,
                        E_total / E0 - 1.);
          pcout << line;
        }
    };

    record(0, 0.);

    loop_timer.restart();
    for (unsigned int step = 1; step <= n_steps; ++step)
      {
        const double t         = step * dt;
        const double alpha_old = contact.alpha;
        const double F_old     = contact.force;

        stepper->advance(step, t, ball, contact);

        // Trapezoidal impulse: consistent with both schemes' impactor
        // update, m (v_{n+1} - v_n) = -dt (F_n + F_{n+1})/2 for gamma = 1/2.
        impulse += 0.5 * dt * (F_old + contact.force);

        // Contact episodes; separation time by linear interpolation of the
        // indentation's zero crossing (second-order accurate).
        const bool now_in_contact = (contact.alpha > 0.);
        if (in_contact && !now_in_contact && !separated_once)
          {
            separated_once = true;
            separation_time =
              t - dt + dt * alpha_old / (alpha_old - contact.alpha);
          }
        if (!in_contact && now_in_contact)
          ++n_impacts;
        in_contact = now_in_contact;

        record(step, t);
      }
    if (vtu)
      {
        output_timer.start();
        vtu->finish();
        output_timer.stop();
      }
    loop_timer.stop();

    results.n_time_steps     = n_steps;
    results.impulse          = impulse;
    results.n_impacts        = n_impacts;
    results.contact_duration = separation_time;
    results.departure_velocity =
      in_contact ? std::numeric_limits<double>::quiet_NaN() : -ball.v;
    // Momentum balance of the impactor: int F dt = m (V0 + V_departure),
    // evaluated at the end of the run with its current velocity.
    results.momentum_balance_error =
      std::abs(impulse - m_i * (V0 - ball.v)) / (m_i * V0);

    if (in_contact || !separated_once)
      pcout << "  WARNING: the impactor is still in contact at the end time; "
               "contact_duration and departure_velocity are not defined "
               "(raise Time integration/End time).\n";
    if (n_impacts > 1)
      pcout << "  note: the impactor struck the plate " << n_impacts
            << " times.\n";

    results.output_time    = output_timer.wall_time();
    results.time_loop_time = loop_timer.wall_time() - results.output_time;
    results.wall_time      = total_timer.wall_time();

    write_summary();

    char line[400];
    std::snprintf(line,
                  sizeof(line),
                  "  peak force %.3f N at %.3f us; contact %.3f us; departure "
                  "velocity %.6f m/s\n"
                  "  max indentation %.4f um, mid-plane deflection %.4f um, "
                  "top deflection %.4f um\n"
                  "  energy drift %.3e, momentum balance error %.3e\n",
                  results.peak_contact_force,
                  results.time_of_peak_force * 1e6,
                  results.contact_duration * 1e6,
                  results.departure_velocity,
                  results.max_indentation * 1e6,
                  results.max_midplane_deflection * 1e6,
                  results.max_top_deflection * 1e6,
                  results.max_energy_drift,
                  results.momentum_balance_error);
    pcout << line;
    if (parameters.print_timing)
      pcout << "  wall time " << results.wall_time << " s (setup "
            << results.setup_time << " s, factorization "
            << results.factorization_time << " s, time loop "
            << results.time_loop_time
            << " s = " << 1e3 * results.time_loop_time / std::max(n_steps, 1u)
            << " ms per step, output " << results.output_time << " s)\n";
  }



  void
  ImpactSimulator::write_summary() const
  {
    if (Utilities::MPI::this_mpi_process(mpi_communicator) != 0)
      return;
    std::ofstream out(parameters.output_directory + "/summary.txt");
    AssertThrow(out, ExcMessage("cannot write summary.txt"));
    auto put = [&](const char *name, const double value, const int decimals) {
      char buffer[200];
      std::snprintf(
        buffer, sizeof(buffer), "%s = %.*f\n", name, decimals, value);
      out << buffer;
    };
    auto put_e = [&](const char *name, const double value) {
      char buffer[200];
      std::snprintf(buffer, sizeof(buffer), "%s = %.6e\n", name, value);
      out << buffer;
    };
    const ImpactResults &r = results;
    put("peak_contact_force_N", r.peak_contact_force, 4);
    put("max_sampled_contact_force_N", r.max_sampled_force, 4);
    put("time_of_peak_force_us", r.time_of_peak_force * 1e6, 4);
    put("contact_duration_us", r.contact_duration * 1e6, 4);
    put("departure_velocity_m_s", r.departure_velocity, 7);
    put("max_indentation_um", r.max_indentation * 1e6, 5);
    put("max_midplane_deflection_um", r.max_midplane_deflection * 1e6, 5);
    put("max_top_deflection_um", r.max_top_deflection * 1e6, 5);
    put_e("contact_stiffness_Kh_N_m1.5", r.contact_stiffness);
    put_e("contact_modulus_Q_Pa", r.contact_modulus);
    put("impactor_mass_kg", r.impactor_mass, 8);
    put("plate_mass_kg", r.plate_mass, 8);
    put("impulse_N_s", r.impulse, 9);
    put("contact_node_offset_mm", r.contact_node_offset * 1e3, 6);
    put("n_impacts", r.n_impacts, 0);
    put("n_dofs", r.n_dofs, 0);
    put("n_mpi_ranks", r.n_mpi_ranks, 0);
    put("n_time_steps", r.n_time_steps, 0);
    put("max_newton_iterations", r.max_newton_iterations, 0);
    put_e("max_relative_energy_drift", r.max_energy_drift);
    put_e("momentum_balance_error", r.momentum_balance_error);
    put("setup_s", r.setup_time, 3);
    put("factorization_s", r.factorization_time, 3);
    put("time_loop_s", r.time_loop_time, 3);
    put("time_per_step_ms", 1e3 * r.time_loop_time / r.n_time_steps, 4);
    put("output_s", r.output_time, 3);
    put("spmv_ms", 1e3 * r.spmv_time, 4);
    put("solve_ms", 1e3 * r.solve_time, 4);
    put("wall_time_s", r.wall_time, 3);
  }
} // namespace fgimpact
