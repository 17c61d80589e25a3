#include <deal.II/base/exceptions.h>

#include <fgimpact/app/run_control.h>
#include <fgimpact/output/impact_summary.h>
#include <fgimpact/output/monitor.h>
#include <fgimpact/output/output_files.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

namespace fgimpact
{
  ImpactMonitor::ImpactMonitor(const OutputParameters &parameters,
                               const PlateModel       &plate,
                               const ContactModel     &contact,
                               const double            impactor_mass,
                               const double            impact_velocity,
                               const double            dt,
                               const unsigned int      n_steps,
                               ImpactResults          &results,
                               CheckpointReader       *resume)
    : parameters(parameters)
    , contact_model(contact)
    , m_i(impactor_mass)
    , V0(impact_velocity)
    , E0(0.5 * impactor_mass * impact_velocity * impact_velocity)
    , dt(dt)
    , n_steps(n_steps)
    , root(Utilities::MPI::this_mpi_process(plate.get_mpi_communicator()) == 0)
    , whole(1. / plate.get_geometry().share())

    , pcout(std::cout, root)
    , impact_results(results)
    , mid_probe(plate, history_probe_points(plate.get_geometry())[0])
    , top_probe(plate, history_probe_points(plate.get_geometry())[1])
    , fields(plate)
    , progress(n_steps, root && parameters.print_timing)
  {
    plate_communicator = plate.get_mpi_communicator();
    output_timer.stop();
    output_timer.reset();
    // A fresh run: the time history's entries start from nothing.
    impact_results.peak_contact_force = impact_results.max_sampled_force = 0;
    impact_results.time_of_peak_force = impact_results.impulse = 0;
    impact_results.max_indentation = impact_results.max_energy_drift = 0;
    impact_results.max_contact_radius = impact_results.max_contact_pressure = 0;
    impact_results.max_contact_nodes                                        = 0;
    impact_results.max_midplane_deflection                                  = 0;
    impact_results.max_top_deflection                                       = 0;
    impact_results.max_newton_iterations                                    = 0;
    impact_results.linear_iterations                                        = 0;
    impact_results.max_linear_iterations                                    = 0;
    impact_results.contact_duration = std::numeric_limits<double>::quiet_NaN();
    impact_results.n_impacts        = 1;
    columns                         = history_columns();
    if (contact.reports_contact_area())
      columns.insert(columns.end(),
                     contact_area_columns().begin(),
                     contact_area_columns().end());
    if (resume)
      load(*resume);
    if (!parameters.probe_points.points.empty())
      probe_set =
        std::make_unique<ProbeSet>(plate, parameters.probe_points.points);
    if (root)
      open_csv_files();
    if (parameters.vtu_interval > 0)
      vtu = std::make_unique<VtuWriter>(plate,
                                        parameters.directory,
                                        parameters.vtu_compression,
                                        parameters.vtu_fields);
    if (vtu && resume)
      vtu->restore(vtu_records);
  }



  void
  ImpactMonitor::open_csv_files()
  {
    // Rank 0 alone opens the CSV files: a failure (disk full, a resumed
    // file too short) is kept in output_failure() as in record(), for the
    // driver to agree on over the ranks before any collective output.
    try
      {
        std::vector<std::pair<std::string, int>> header;
        for (const auto &column : columns)
          header.emplace_back(column.name, column.decimals);
        history =
          std::make_unique<CsvWriter>(parameters.directory + "/history.csv",
                                      header,
                                      history_length);
        if (probe_set)
          probe_csv =
            std::make_unique<CsvWriter>(parameters.directory + "/probes.csv",
                                        probe_set->columns(),
                                        probe_length);
      }
    catch (const ExceptionBase &e)
      {
        output_failure_message = message_of(e);
        history.reset();
        probe_csv.reset();
      }
  }



  void
  ImpactMonitor::add_contact_output(const Point<3> &impact_point,
                                    const double    sphere_radius)
  {
    if (parameters.vtu_interval > 0 && root)
      {
        contact_vtu = std::make_unique<ContactVtuWriter>(parameters.directory,
                                                         impact_point,
                                                         sphere_radius,
                                                         contact_model);
        if (!sphere_records.empty())
          contact_vtu->restore(sphere_records, contact_records);
      }
  }



  void
  ImpactMonitor::add_row_observer(const RowObserver &observer)
  {
    observers.push_back(observer);
  }



  void
  ImpactMonitor::record(const unsigned int   step,
                        const double         t,
                        const TimeStepper   &stepper,
                        const ImpactorState &ball,
                        const ContactState  &part_contact)
  {
    // The rates only when a probe or a snapshot reads them (decided from
    // the parameters, the same on every rank: distribute() is collective).
    const bool snapshot =
      parameters.vtu_interval > 0 && step % parameters.vtu_interval == 0;
    fields.update(stepper, snapshot || probe_set != nullptr);
    PlateSample plate =
      probe_plate(mid_probe, top_probe, fields.displacement());
    // The energies from the condensed vectors: u^T K u is the same.
    plate.E_kinetic         = stepper.kinetic_energy();
    plate.E_strain          = stepper.strain_energy();
    plate.linear_iterations = stepper.linear_iterations();
    record(step, t, plate, ball, part_contact, &fields);
  }



  void
  ImpactMonitor::record(const unsigned int   step,
                        const double         t,
                        const PlateSample   &plate,
                        const ImpactorState &ball,
                        const ContactState  &part_contact,
                        const PlateFields   *fields)
  {
    // A symmetric part: the whole plate's contact force is the part's
    // times 1/share; everything below is the whole plate's.
    if (whole != 1.)
      {
        whole_contact = part_contact;
        whole_contact.force *= whole;
      }
    const ContactState &contact = (whole != 1. ? whole_contact : part_contact);
    if (step > 0)
      {
        // Trapezoidal impulse: consistent with both schemes' impactor
        // update, m (v_{n+1} - v_n) = -dt (F_n + F_{n+1})/2 for gamma = 1/2.
        impact_results.impulse += 0.5 * dt * (last_force + contact.force);
        update_episodes(t, contact);
      }

    HistorySample sample;
    sample.t          = t;
    sample.ball       = &ball;
    sample.contact    = &contact;
    sample.W_mid      = plate.W_mid;
    sample.W_top      = plate.W_top;
    sample.sigma_mid  = plate.sigma_mid;
    sample.E_impactor = 0.5 * m_i * ball.v * ball.v;
    sample.E_kinetic  = whole * plate.E_kinetic;
    sample.E_strain   = whole * plate.E_strain;
    // A model without a potential (hertz midplane: the force acts at the
    // top node, alpha is measured at the mid-plane) stores the work of the
    // contact force on the approach at the top node, int F d(w + u_top)
    // (trapezoidal: exact for the average-acceleration rule).
    const double approach = ball.w + contact.node_displacement;
    if (!contact_model.has_potential() && step > 0)
      contact_work +=
        0.5 * (last_force + contact.force) * (approach - last_approach);
    sample.E_contact = contact_model.has_potential() ?
                         whole * contact_model.potential(part_contact) :
                         contact_work;
    sample.E_total =
      sample.E_impactor + sample.E_kinetic + sample.E_strain + sample.E_contact;

    // The convolution engine of a study has no fields: it clears the
    // probe points (probes.csv comes from --study-case K).
    if (probe_set && fields)
      {
        ProbeValues values = probe_set->evaluate(fields->displacement(),
                                                 fields->velocity(),
                                                 fields->acceleration(),
                                                 fields->lumped_mass());
        values.support_reaction_z *= whole; // a part's supports: scaled up
        probe_row = probe_set->row(t, values);
      }
    update_extremes(t, sample);
    report_lcp_fallback(step, t, part_contact);
    watch_energy(step, t, std::abs(sample.E_total - E0) / E0);
    impact_results.linear_iterations += plate.linear_iterations;
    impact_results.max_linear_iterations =
      std::max(impact_results.max_linear_iterations, plate.linear_iterations);
    write_outputs(step, t, fields, sample);
    last_force    = contact.force;
    last_alpha    = contact.alpha;
    last_approach = approach;
  }



  void
  ImpactMonitor::report_lcp_fallback(const unsigned int  step,
                                     const double        t,
                                     const ContactState &contact)
  {
    // Rare (PDAS settles in a few iterations for contact Delassus
    // matrices): say so once, with what the fallback left.
    if (!contact.used_lcp_fallback || lcp_fallback_reported)
      return;
    lcp_fallback_reported = true;
    char line[320];
    std::snprintf(line,
                  sizeof(line),
                  "  note: at time step %u (t = %.3f us) the contact's "
                  "active-set iteration did not settle; projected "
                  "Gauss-Seidel finished the solve (largest penetration "
                  "left %.3e um); later such steps are not reported.\n",
                  step,
                  t * 1e6,
                  contact.residual_penetration * 1e6);
    pcout << line;
  }



  void
  ImpactMonitor::update_episodes(const double t, const ContactState &contact)
  {
    // Separation time by linear interpolation of the indentation's zero
    // crossing (second-order accurate).
    const bool now_in_contact = (contact.alpha > 0.);
    if (in_contact && !now_in_contact && !separated_once)
      {
        separated_once = true;
        impact_results.contact_duration =
          t - dt + dt * last_alpha / (last_alpha - contact.alpha);
      }
    if (!in_contact && now_in_contact)
      ++impact_results.n_impacts;
    in_contact = now_in_contact;
  }



  void
  ImpactMonitor::update_extremes(const double t, const HistorySample &sample)
  {
    ImpactResults &r = impact_results;
    const double   F = sample.contact->force;
    r.max_energy_drift =
      std::max(r.max_energy_drift, std::abs(sample.E_total - E0) / E0);
    // Peak force: the parabola through the largest sample and its two
    // neighbours (second-order accurate in dt, unlike the largest sample,
    // whose error depends on where the samples fall).
    if (F > r.max_sampled_force)
      {
        r.max_sampled_force  = F;
        r.peak_contact_force = F;
        r.time_of_peak_force = t;
        peak_left            = last_force;
        peak_pending         = true;
      }
    else if (peak_pending)
      {
        const double Fm = r.max_sampled_force;
        const double d  = peak_left - 2. * Fm + F;
        if (d < 0.)
          {
            r.peak_contact_force =
              Fm - (peak_left - F) * (peak_left - F) / (8. * d);
            r.time_of_peak_force = t - dt + dt * (peak_left - F) / (2. * d);
          }
        peak_pending = false;
      }
    r.max_indentation = std::max(r.max_indentation, sample.contact->alpha);
    r.max_contact_radius =
      std::max(r.max_contact_radius, sample.contact->contact_radius);
    r.max_contact_pressure =
      std::max(r.max_contact_pressure, sample.contact->max_pressure);
    r.max_contact_nodes =
      std::max(r.max_contact_nodes, sample.contact->n_active);
    r.max_midplane_deflection =
      std::max(r.max_midplane_deflection, sample.W_mid);
    r.max_top_deflection = std::max(r.max_top_deflection, sample.W_top);
    r.max_newton_iterations =
      std::max(r.max_newton_iterations, sample.contact->newton_iterations);
  }



  void
  ImpactMonitor::watch_energy(const unsigned int step,
                              const double       t,
                              const double       drift)
  {
    // Implicit Newmark conserves the discrete energy up to the contact's
    // quadrature error (1e-4..1e-3 on the paper's cases); 0.5 is far
    // beyond any accurate run, and NaN fails the test too.
    const double warning_level = 1e-2, stop_level = 0.5;
    char         where[100];
    std::snprintf(
      where, sizeof(where), "time step %u (t = %.3f us)", step, t * 1e6);
    if (!(drift <= stop_level))
      {
        char text[100];
        std::snprintf(text, sizeof(text), "%.3e", drift);
        AssertThrow(false,
                    ExcNumericalFailure(
                      std::string("the run is blowing up: the relative "
                                  "energy drift reached ") +
                      text + " (limit 0.5) at " + where +
                      "; reduce Time integration/Time step, use Time "
                      "integration/Scheme = implicit with Newmark beta = "
                      "0.25, gamma = 0.5, or lower Time integration/Stable "
                      "step safety factor."));
      }
    if (drift > warning_level && !drift_warned)
      {
        drift_warned = true;
        char text[300];
        std::snprintf(text,
                      sizeof(text),
                      "  WARNING: the relative energy drift reached %.3e at "
                      "%s; above 1e-2 the results may be inaccurate: reduce "
                      "Time integration/Time step.\n",
                      drift,
                      where);
        pcout << text;
      }
  }



  void
  ImpactMonitor::write_outputs(const unsigned int   step,
                               const double         t,
                               const PlateFields   *fields,
                               const HistorySample &sample)
  {
    std::vector<double> row;
    row.reserve(columns.size());
    for (const auto &column : columns)
      row.push_back(column.value(sample));
    // A failed write stops the writing on this rank; the driver stops
    // every rank at the end of this step (no rank waits for another).
    try
      {
        if (history)
          history->write_row(row);
        if (probe_csv)
          probe_csv->write_row(probe_row);
        if (vtu && fields && step % parameters.vtu_interval == 0)
          {
            output_timer.start();
            vtu->write(step,
                       t,
                       fields->displacement(),
                       fields->velocity(),
                       {},
                       &fields->acceleration());
            if (contact_vtu)
              contact_vtu->write(step, t, sample.ball->w, *sample.contact);
            output_timer.stop();
          }
      }
    catch (const ExceptionBase &e)
      {
        std::ostringstream message;
        e.print_info(message);
        output_failure_message = one_line(message.str());
        history.reset();
        probe_csv.reset();
        vtu.reset();
        contact_vtu.reset();
      }
    for (const auto &observer : observers)
      observer(row);

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
                      sample.contact->force,
                      sample.contact->alpha * 1e6,
                      sample.W_mid * 1e6,
                      sample.E_total / E0 - 1.);
        pcout << line;
      }
    progress.update(step, std::cout);
  }



  void
  ImpactMonitor::close_output()
  {
    output_timer.start();
    try
      {
        if (contact_vtu)
          contact_vtu->finish();
        // The peak fields are written collectively: only if no rank's
        // VTU output failed (a failed rank has dropped its writer).
        const bool all_writing =
          Utilities::MPI::min(vtu ? 1u : 0u, plate_communicator) == 1u;
        if (vtu && all_writing)
          vtu->write_peak_fields(); // finishes the series first
        else if (vtu)
          vtu->finish();
        if (history)
          history->flush();
        if (probe_csv)
          probe_csv->flush();
      }
    catch (const ExceptionBase &e)
      {
        std::ostringstream message;
        e.print_info(message);
        output_failure_message = one_line(message.str());
      }
    output_timer.stop();
  }



  void
  ImpactMonitor::finish(const ImpactorState &ball,
                        const unsigned int   steps_done,
                        const std::string   &status,
                        const double         loop_time,
                        const double         wall_time)
  {
    ImpactResults &r = impact_results;
    r.n_time_steps   = steps_done;
    // The candidate set may have grown during the run.
    r.n_contact_candidates = contact_model.contact_dofs().size();
    // A symmetric part: the model counts the whole plate's candidates.
    if (whole != 1.)
      contact_model.fill_results(r);
    r.departure_velocity =
      in_contact ? std::numeric_limits<double>::quiet_NaN() : -ball.v;
    // int F dt = m (V0 + V_departure), with the ball's current velocity.
    r.impulse_identity_error =
      std::abs(r.impulse - m_i * (V0 - ball.v)) / (m_i * V0);

    if (in_contact || !separated_once)
      pcout << "  WARNING: the impactor is still in contact at the last time "
               "step; contact_duration and departure_velocity do not exist "
               "and are written as 'none' (raise Time integration/End "
               "time).\n";
    if (r.n_impacts > 1)
      pcout << "  note: the impactor struck the plate " << r.n_impacts
            << " times.\n";
    r.warnings = resolution_warnings(r, contact_model.reports_contact_area());
    for (const auto &warning : r.warnings)
      pcout << "  WARNING: " << warning << ".\n";

    r.output_time    = output_timer.wall_time();
    r.time_loop_time = loop_time - r.output_time;
    r.wall_time      = wall_time;

    write_summary(status, steps_done * dt);
    print_results();
  }



  void
  ImpactMonitor::print_results() const
  {
    const ImpactResults &r = impact_results;
    // A quantity that does not exist is printed as "none".
    const auto optional = [](const double value, const char *format) {
      char text[40] = "none";
      if (std::isfinite(value))
        std::snprintf(text, sizeof(text), format, value);
      return std::string(text);
    };
    char line[400];
    std::snprintf(line,
                  sizeof(line),
                  "  peak force %.3f N at %.3f us; contact %s us; departure "
                  "velocity %s m/s\n"
                  "  max indentation %.4f um, mid-plane deflection %.4f um, "
                  "top deflection %.4f um\n"
                  "  energy drift %.3e\n",
                  r.peak_contact_force,
                  r.time_of_peak_force * 1e6,
                  optional(r.contact_duration * 1e6, "%.3f").c_str(),
                  optional(r.departure_velocity, "%.6f").c_str(),
                  r.max_indentation * 1e6,
                  r.max_midplane_deflection * 1e6,
                  r.max_top_deflection * 1e6,
                  r.max_energy_drift);
    pcout << line;
    if (r.linear_iterations > 0)
      pcout << "  linear solver: " << r.linear_iterations
            << " iterations in all, at most " << r.max_linear_iterations
            << " in one step\n";
    if (parameters.print_timing)
      pcout << "  wall time " << r.wall_time << " s (setup " << r.setup_time
            << " s, factorization " << r.factorization_time << " s, time loop "
            << r.time_loop_time
            << " s = " << 1e3 * r.time_loop_time / std::max(r.n_time_steps, 1u)
            << " ms per step, output " << r.output_time << " s)\n";
  }



  void
  ImpactMonitor::write_summary(const std::string &status,
                               const double       t_end) const
  {
    if (root)
      write_impact_summary(parameters.directory + "/summary.txt",
                           impact_results,
                           contact_model.reports_contact_area(),
                           parameters.instrumentation,
                           status,
                           t_end);
  }
} // namespace fgimpact
