#include <deal.II/base/exceptions.h>

#include <fgimpact/output/impact_summary.h>
#include <fgimpact/output/monitor.h>

#include <cmath>
#include <cstdio>
#include <limits>

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
                               SummaryFile            &summary,
                               const bool              plastic)
    : parameters(parameters)
    , plate(plate)
    , contact_model(contact)
    , m_i(impactor_mass)
    , V0(impact_velocity)
    , E0(0.5 * impactor_mass * impact_velocity * impact_velocity)
    , dt(dt)
    , n_steps(n_steps)
    , whole(1. / plate.get_geometry().share())
    , pcout(std::cout,
            Utilities::MPI::this_mpi_process(plate.get_mpi_communicator()) == 0)
    , impact_results(results)
    , summary(summary)
    , mid_probe(plate, history_probe_points(plate.get_geometry())[0])
    , top_probe(plate, history_probe_points(plate.get_geometry())[1])
    , fields(plate)
  {
    output_timer.stop();
    output_timer.reset();
    auto accumulator = std::make_unique<ResultsAccumulator>(
      results, contact, m_i, V0, dt, whole != 1., pcout);
    results_accumulator = accumulator.get();
    add(std::move(accumulator));
    add(std::make_unique<EnergyWatchdog>(pcout, blow_up_advice));
    auto columns = history_columns();
    if (contact.reports_contact_area())
      columns.insert(columns.end(),
                     contact_area_columns().begin(),
                     contact_area_columns().end());
    if (plastic)
      columns.insert(columns.end(),
                     plasticity_columns().begin(),
                     plasticity_columns().end());
    auto history_writer = std::make_unique<HistoryWriter>(parameters.directory,
                                                          columns,
                                                          pcout.is_active());
    history             = history_writer.get();
    add(std::move(history_writer));
    if (!parameters.probe_points.points.empty())
      {
        auto set =
          std::make_unique<ProbeSet>(plate, parameters.probe_points.points);
        probe_set = set.get();
        add(std::make_unique<ProbeWriter>(std::move(set),
                                          results.probe_peaks,
                                          parameters.directory,
                                          whole,
                                          pcout.is_active()));
      }
  }



  void
  ImpactMonitor::set_plasticity(const PlasticPlate &plasticity)
  {
    mid_probe.set_plasticity(plasticity);
    top_probe.set_plasticity(plasticity);
    if (probe_set)
      probe_set->set_plasticity(plasticity);
  }



  void
  ImpactMonitor::set_prestress(const InitialStress &initial)
  {
    initial_stress = &initial;
    mid_probe.set_prestress(initial);
    top_probe.set_prestress(initial);
    if (probe_set)
      probe_set->set_prestress(plate, initial);
  }



  void
  ImpactMonitor::add_row_observer(const RowObserver &observer)
  {
    history->add_observer(observer);
  }



  void
  ImpactMonitor::add(std::unique_ptr<Postprocessor> postprocessor)
  {
    postprocessors.push_back(std::move(postprocessor));
  }



  void
  ImpactMonitor::add_field_output(const Point<3>     &impact_point,
                                  const double        sphere_radius,
                                  const PlasticPlate *plasticity)
  {
    if (!parameters.writes_vtu())
      return;
    auto writer = std::make_unique<FieldWriter>(plate,
                                                parameters,
                                                contact_model,
                                                impact_point,
                                                sphere_radius,
                                                results_accumulator);
    if (plasticity)
      writer->set_plasticity(*plasticity);
    if (initial_stress)
      writer->set_prestress(*initial_stress);
    add(std::move(writer));
  }



  std::string
  ImpactMonitor::section_name(const Postprocessor &postprocessor)
  {
    return "monitor: " + postprocessor.name();
  }



  void
  ImpactMonitor::start(const CheckpointReader *resume)
  {
    // The screen log last: its line follows the step's files.
    add(std::make_unique<RunLog>(parameters.log_interval,
                                 n_steps,
                                 E0,
                                 parameters.print_timing,
                                 pcout,
                                 expected_steps));
    if (resume)
      {
        CheckpointReader in = resume->section("monitor", checkpoint_version);
        for (double *value : {&last_force, &last_approach, &contact_work})
          in.get(*value);
        for (const auto &p : postprocessors)
          if (!p->name().empty())
            {
              CheckpointReader section =
                resume->section(section_name(*p), p->checkpoint_version());
              p->load(section);
            }
        // A file that cannot be continued: none is opened (the driver
        // refuses the resume, every file as it was).
        if (Utilities::MPI::max(output_failure().empty() ? 0 : 1,
                                plate.get_mpi_communicator()) > 0)
          return;
      }
    for (const auto &p : postprocessors)
      p->start();
  }



  void
  ImpactMonitor::record(const unsigned int   step,
                        const double         t,
                        const TimeStepper   &stepper,
                        const ImpactorState &ball,
                        const ContactState  &part_contact)
  {
    // The rates only when a postprocessor reads them (decided from the
    // parameters, the same on every rank: distribute() is collective).
    bool rates = false;
    for (const auto &p : postprocessors)
      rates = rates || p->needs_rates(step);
    fields.update(stepper, rates);
    PlateSample plate =
      probe_plate(mid_probe, top_probe, fields.displacement());
    // The energies from the condensed vectors: u^T K u is the same.
    plate.E_kinetic          = stepper.kinetic_energy();
    plate.E_strain           = stepper.strain_energy();
    plate.E_plastic          = stepper.plastic_work();
    plate.max_plastic_strain = stepper.max_plastic_strain();
    plate.linear_iterations  = stepper.linear_iterations();
    record(step, t, plate, ball, part_contact, &fields);
  }



  HistorySample
  ImpactMonitor::make_sample(const unsigned int   step,
                             const double         t,
                             const PlateSample   &plate,
                             const ImpactorState &ball,
                             const ContactState  &part_contact)
  {
    // A symmetric part: the whole plate's contact force is the part's
    // times 1/share; everything below is the whole plate's.
    whole_contact = part_contact;
    whole_contact.force *= whole;

    HistorySample sample;
    sample.t          = t;
    sample.ball       = &ball;
    sample.contact    = &whole_contact;
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
    const double approach = ball.w + part_contact.node_displacement;
    if (!contact_model.has_potential() && step > 0)
      contact_work +=
        0.5 * (last_force + whole_contact.force) * (approach - last_approach);
    sample.E_contact          = contact_model.has_potential() ?
                                  whole * contact_model.potential(part_contact) :
                                  contact_work;
    sample.E_plastic          = whole * plate.E_plastic;
    sample.max_plastic_strain = plate.max_plastic_strain;
    sample.E_total = sample.E_impactor + sample.E_kinetic + sample.E_strain +
                     sample.E_contact + sample.E_plastic;
    last_force    = whole_contact.force;
    last_approach = approach;
    return sample;
  }



  void
  ImpactMonitor::record(const unsigned int   step,
                        const double         t,
                        const PlateSample   &plate,
                        const ImpactorState &ball,
                        const ContactState  &part_contact,
                        const PlateFields   *fields)
  {
    const HistorySample sample =
      make_sample(step, t, plate, ball, part_contact);
    StepRecord record;
    record.step              = step;
    record.t                 = t;
    record.sample            = &sample;
    record.part_contact      = &part_contact;
    record.fields            = fields;
    record.linear_iterations = plate.linear_iterations;
    record.energy_drift      = std::abs(sample.E_total - E0) / E0;
    for (const auto &p : postprocessors)
      p->execute(record);
  }



  void
  ImpactMonitor::save(CheckpointWriter &out, const unsigned int step)
  {
    out.section("monitor", checkpoint_version, [&](CheckpointWriter &s) {
      for (const double value : {last_force, last_approach, contact_work})
        s.put(value);
    });
    for (const auto &p : postprocessors)
      if (!p->name().empty())
        out.section(section_name(*p),
                    p->checkpoint_version(),
                    [&](CheckpointWriter &s) { p->save(s, step); });
  }



  void
  ImpactMonitor::resume_output(const unsigned int step,
                               const double       t,
                               const TimeStepper &stepper)
  {
    // Every rank alike (each writes its piece).
    for (const auto &p : postprocessors)
      if (p->needs_rewrite())
        {
          fields.update(stepper, true);
          p->rewrite(step, t, fields);
        }
  }



  void
  ImpactMonitor::close_output()
  {
    output_timer.start();
    for (const auto &p : postprocessors)
      p->close_output();
    output_timer.stop();
  }



  const std::string &
  ImpactMonitor::output_failure() const
  {
    for (const auto &p : postprocessors)
      if (!p->output_failure().empty())
        return p->output_failure();
    static const std::string none;
    return none;
  }



  std::string
  ImpactMonitor::agreed_output_failure() const
  {
    for (const auto &m :
         Utilities::MPI::all_gather(plate.get_mpi_communicator(),
                                    output_failure()))
      if (!m.empty())
        return m;
    return "";
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
    for (const auto &p : postprocessors)
      p->finish(ball);
    if (ball_results_void)
      {
        r.departure_velocity = std::numeric_limits<double>::quiet_NaN();
        r.contact_duration   = std::numeric_limits<double>::quiet_NaN();
      }

    // close_output()'s time, and the snapshots' (FieldWriter's).
    double output_time = output_timer.wall_time();
    for (const auto &p : postprocessors)
      output_time += p->output_time();
    r.output_time    = output_time;
    r.time_loop_time = loop_time - r.output_time;
    r.wall_time      = wall_time;

    summary.write(impact_summary(impact_results,
                                 contact_model.reports_contact_area(),
                                 parameters.instrumentation,
                                 status,
                                 steps_done * dt));
    print_results();
  }



  namespace
  {
    /// A quantity that may not exist, printed with `format` or as "none".
    std::string
    value_or_none(const double value, const char *format)
    {
      char text[40] = "none";
      if (std::isfinite(value))
        std::snprintf(text, sizeof(text), format, value);
      return std::string(text);
    }

    /// The log's line of a plastic run's results.
    std::string
    plastic_line(const ImpactResults::Plastic &p)
    {
      char line[400];
      std::snprintf(line,
                    sizeof(line),
                    "  plastic work %.6f J, crater %.4f um, largest "
                    "equivalent plastic strain %.5f, first yield at %s us "
                    "(%s N), restitution %s; plate iterations %.3f per "
                    "step, at most %u\n",
                    p.dissipation,
                    p.permanent_indentation * 1e6,
                    p.max_plastic_strain,
                    value_or_none(p.first_yield_time * 1e6, "%.3f").c_str(),
                    value_or_none(p.first_yield_force, "%.3f").c_str(),
                    value_or_none(p.restitution, "%.5f").c_str(),
                    p.mean_iterations,
                    p.max_iterations);
      return line;
    }
  } // namespace



  void
  ImpactMonitor::print_results() const
  {
    const ImpactResults &r = impact_results;
    char                 line[400];
    std::snprintf(line,
                  sizeof(line),
                  "  peak force %.3f N at %.3f us; contact %s us; departure "
                  "velocity %s m/s\n"
                  "  max %s %.4f um, approach %.4f um, mid-plane "
                  "deflection %.4f um, top deflection %.4f um\n"
                  "  energy drift %.3e\n",
                  r.peak_contact_force,
                  r.time_of_peak_force * 1e6,
                  value_or_none(r.contact_duration * 1e6, "%.3f").c_str(),
                  value_or_none(r.departure_velocity, "%.6f").c_str(),
                  contact_model.reports_contact_area() ?
                    "Hertz indentation (from the force)" :
                    "indentation",
                  r.max_indentation * 1e6,
                  r.max_approach * 1e6,
                  r.max_midplane_deflection * 1e6,
                  r.max_top_deflection * 1e6,
                  r.max_energy_drift);
    pcout << line;
    if (r.plastic.modelled)
      pcout << plastic_line(r.plastic);
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
} // namespace fgimpact
