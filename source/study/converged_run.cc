#include <deal.II/base/timer.h>

#include <fgimpact/app/resources.h>
#include <fgimpact/app/run_control.h>
#include <fgimpact/app/scene.h>
#include <fgimpact/app/simulator.h>
#include <fgimpact/material/material.h>
#include <fgimpact/plate/geometry.h>
#include <fgimpact/plate/symmetry.h>
#include <fgimpact/study/converged_run.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <malloc.h>
#include <sstream>

namespace fgimpact
{
  namespace
  {
    /// Geometry/Contact refinement levels' upper bound (its pattern).
    constexpr unsigned int max_levels = 12;

    /// The scene of parameters p without the mesh (cheap): its expected
    /// contact radius and impact point.
    Scene
    scene_of(const Parameters &p)
    {
      const SymmetricPart              part = resolve_symmetry(p);
      const PlateGeometry              geometry(p.geometry, part.cut);
      const FunctionallyGradedMaterial material(p.material,
                                                geometry.thickness());
      return Scene(p, material, geometry.share());
    }

    /// Give the freed heap of a finished level back to the system: glibc
    /// keeps it otherwise, and the next level's peak would stack on it
    /// (default scene: 0.47 GB resident after level 6 instead of 0.18 GB,
    /// and the final run at level 7 2.35 GB instead of 1.6 GB).
    void
    release_freed_memory()
    {
      malloc_trim(0);
    }

    std::string
    percent(const double relative)
    {
      char text[40];
      std::snprintf(text, sizeof(text), "%.3f %%", 100. * relative);
      return text;
    }
  } // namespace



  const std::vector<ConvergedRun::Quantity> &
  ConvergedRun::quantities()
  {
    static const std::vector<Quantity> q = {
      {"peak_contact_force",
       "peak_contact_force_N",
       1.,
       [](const ImpactResults &r) { return r.peak_contact_force; }},
      {"contact_duration",
       "contact_duration_us",
       1e6,
       [](const ImpactResults &r) { return r.contact_duration; }},
      {"departure_velocity",
       "departure_velocity_m_s",
       1.,
       [](const ImpactResults &r) { return r.departure_velocity; }},
      {"max_midplane_deflection",
       "max_midplane_deflection_um",
       1e6,
       [](const ImpactResults &r) { return r.max_midplane_deflection; }},
      {"max_approach",
       "max_approach_um",
       1e6,
       [](const ImpactResults &r) { return r.max_approach; }}};
    return q;
  }



  std::vector<ConvergedRun::Quantity>
  ConvergedRun::quantities_of(const ImpactResults &r) const
  {
    std::vector<Quantity> all   = quantities();
    const Point<3>        point = scene_of(parameters).impact_point();
    const double reach = r.max_contact_radius + r.model.element_size_under_ball;
    for (std::size_t i = 0; i < r.probe_peaks.size(); ++i)
      {
        const auto  &peak = r.probe_peaks[i];
        const double in_plane =
          std::hypot(peak.location[0] - point[0], peak.location[1] - point[1]);
        const bool on_contact =
          std::abs(peak.location[2] - point[2]) <= 1e-9 * r.model.thickness &&
          in_plane <= reach;
        const std::string key = "probe_" + peak.name + "_peak_von_mises";
        all.push_back({key,
                       key + "_MPa",
                       1e-6,
                       [i](const ImpactResults &x) {
                         return x.probe_peaks.at(i).von_mises;
                       },
                       !on_contact});
      }
    return all;
  }



  ConvergedRun::ConvergedRun(
    const Parameters                              &parameters,
    const MPI_Comm                                 communicator,
    SummaryFile                                   &summary,
    const std::vector<ImpactMonitor::RowObserver> &observers)
    : parameters(parameters)
    , communicator(communicator)
    , summary(summary)
    , observers(observers)
    , pcout(std::cout, Utilities::MPI::this_mpi_process(communicator) == 0)
  {}



  ConvergedRun::~ConvergedRun() = default;



  void
  ConvergedRun::setup()
  {
    // One level below the scene's automatic one (4 elements across the
    // Hertz contact radius, accurate to about 1 %): a change needs a run
    // before it, and the coarser one costs about a quarter.  Its set-up
    // checks the input (the mesh included) before anything is written.
    const unsigned int automatic = automatic_contact_refinement_levels(
      parameters, scene_of(parameters).expected_contact_radius());
    first_levels       = automatic > 0 ? automatic - 1 : 0;
    const Parameters p = parameters_of(first_levels, false);
    Timer            timer;
    first = std::make_unique<Simulator>(p, communicator);
    first->setup();
    first_setup_time = timer.wall_time();
  }



  Parameters
  ConvergedRun::parameters_of(const unsigned int levels, const bool final) const
  {
    Parameters p                         = parameters;
    p.accuracy.preset                    = "custom";
    p.geometry.contact_refinement_auto   = false;
    p.geometry.contact_refinement_levels = levels;
    if (final)
      {
        p.time_integration.time_step /= 2.;
        return p;
      }
    p.output.directory = parameters.output.directory + "/convergence/level_" +
                         std::to_string(levels);
    p.output.vtu_interval        = 0;
    p.output.snapshot_times      = {};
    p.output.peak_snapshot       = false;
    p.output.checkpoint_interval = 0;
    return p;
  }



  ConvergedRun::Level
  ConvergedRun::run_one(Simulator &simulator, const Parameters &p)
  {
    Timer timer;
    if (p.output.directory != parameters.output.directory)
      run_on_root(communicator, [&]() { prepare_output_directory(p.output); });
    simulator.run();
    Level level;
    level.levels    = p.geometry.contact_refinement_levels;
    level.time_step = p.time_integration.time_step;
    level.results   = simulator.get_results();
    level.wall_time = timer.wall_time();
    return level;
  }



  void
  ConvergedRun::refuse_unfinished_contact() const
  {
    // A quantity without a value (the ball still in contact at the end:
    // no contact duration, no departure velocity) changes by "inf %" at
    // every level: the sequence would run to its last level for nothing.
    const ImpactResults &r = sequence.back().results;
    for (const Quantity &q : quantities_of(r))
      AssertThrow(!q.steers || std::isfinite(q.value(r)),
                  ExcNumericalFailure(
                    "Accuracy = converged: " + q.key +
                    " has no value at contact refinement level " +
                    std::to_string(sequence.back().levels) +
                    " (the ball is still in contact at Time integration/End "
                    "time, " +
                    std::to_string(static_cast<long long>(std::llround(
                      parameters.time_integration.end_time * 1e6))) +
                    " us); set End time = auto or a later End time."));
  }



  std::pair<double, std::string>
  ConvergedRun::largest_change() const
  {
    std::pair<double, std::string> largest = {0., ""};
    const ImpactResults           &a = sequence[sequence.size() - 2].results,
                        &b           = sequence.back().results;
    for (const Quantity &q : quantities_of(b))
      {
        if (!q.steers)
          continue;
        double change =
          std::abs(q.value(b) - q.value(a)) / std::abs(q.value(b));
        if (!std::isfinite(change))
          change = std::numeric_limits<double>::infinity();
        if (change >= largest.first)
          largest = {change, q.key};
      }
    return largest;
  }



  void
  ConvergedRun::check_fits(const unsigned int levels) const
  {
    // After the first level there is no change yet.
    std::string reached =
      "Accuracy tolerance = " + percent(parameters.accuracy.tolerance) +
      " is not reached by level " + std::to_string(levels - 1);
    if (sequence.size() >= 2)
      {
        const auto [change, key] = largest_change();
        reached += " (" + key + " still changed by " + percent(change) + ")";
      }
    AssertThrow(levels <= max_levels,
                ExcMessage(reached +
                           ", and Geometry/Contact refinement "
                           "levels stops at " +
                           std::to_string(max_levels) +
                           "; raise Accuracy tolerance."));
    const Parameters p = parameters_of(levels, false);
    try
      {
        check_memory(p,
                     estimate_resources(p,
                                        contact_refinement_of(p, scene_of(p))),
                     communicator);
      }
    catch (const ExceptionBase &e)
      {
        AssertThrow(false,
                    ExcMessage(reached + ", and level " +
                               std::to_string(levels) +
                               " does not fit (raise Accuracy tolerance): " +
                               message_of(e)));
      }
  }



  void
  ConvergedRun::run()
  {
    try
      {
        run_sequence();
      }
    catch (const RunInterrupted &e)
      {
        // A level's own message offers --resume of its directory, which
        // would finish that one run, not the sequence: say what to do.
        throw RunInterrupted(
          e.signal,
          "Accuracy = converged interrupted by signal " +
            std::to_string(e.signal) +
            " in the run at contact refinement level " +
            std::to_string(running_levels) +
            (final_started ? " (the final run at half the time step)" : "") +
            ": the sequence of levels cannot be resumed (--resume refuses "
            "Accuracy = converged); run the same command again.");
      }
  }



  void
  ConvergedRun::run_sequence()
  {
    const double tolerance = parameters.accuracy.tolerance;
    pcout << "Accuracy = converged (tolerance " << percent(tolerance)
          << "): contact refinement levels from " << first_levels << " into "
          << parameters.output.directory << "/convergence/\n";
    running_levels = first_levels;
    sequence.push_back(run_one(*first, parameters_of(first_levels, false)));
    sequence.back().wall_time += first_setup_time;
    first.reset();
    refuse_unfinished_contact();
    std::unique_ptr<Simulator> last;
    for (unsigned int levels = first_levels + 1;
         sequence.size() < 2 || largest_change().first >= tolerance;
         ++levels)
      {
        last.reset();
        release_freed_memory(); // the level before's simulator is gone
        check_fits(levels);
        running_levels     = levels;
        const Parameters p = parameters_of(levels, false);
        Timer            timer;
        last = std::make_unique<Simulator>(p, communicator);
        last->setup();
        sequence.push_back(run_one(*last, p));
        sequence.back().wall_time = timer.wall_time();
        const auto [change, key]  = largest_change();
        pcout << "Accuracy = converged: level " << levels
              << ", largest change from level " << levels - 1 << ": "
              << percent(change) << " (" << key << ")\n";
      }
    // The finest level at half the time step, with the user's outputs, on
    // its plate (mesh and matrices; at level 5 of the default scene 0.2 s
    // of the final run's 2.6 s).
    const Parameters p = parameters_of(sequence.back().levels, true);
    pcout << "Accuracy = converged: level " << sequence.back().levels
          << " at half the time step (" << p.time_integration.time_step * 1e6
          << " us), the final run, into " << parameters.output.directory
          << '\n';
    running_levels = sequence.back().levels;
    Timer     timer;
    Simulator simulator(p, communicator);
    simulator.take_plate_of(*last);
    last.reset();
    release_freed_memory(); // the last level's driver is gone
    for (const auto &observer : observers)
      simulator.add_history_observer(observer);
    simulator.setup();
    final_started       = true;
    Level final_run     = run_one(simulator, p);
    final_run.wall_time = timer.wall_time();
    final_results       = final_run.results;
    summary_entries     = simulator.summary().entries();
    write_outputs(final_run);
  }



  std::pair<double, std::string>
  ConvergedRun::estimate(const std::vector<double> &q, const double half)
  {
    const std::size_t k   = q.size() - 1;
    const double      d2  = q[k] - q[k - 1];
    double            e   = std::abs(d2);
    std::string       how = "last change";
    if (k >= 2)
      {
        // Richardson needs changes that shrink by a factor of 2^p with an
        // order p of at least 1/2: below, 1/(2^p - 1) grows without bound
        // (the default scene's mid-plane probe changed by 0.0130 and
        // 0.0129 MPa from level 5 to 7, p = 0.01, which made an estimate
        // of 7.5 % out of changes of 0.08 %) and the sequence shows no
        // order to extrapolate with: the last change, and the order said.
        const double d1 = q[k - 1] - q[k - 2];
        if (d1 * d2 > 0 && std::abs(d2) < std::abs(d1))
          {
            const double p = std::log2(std::abs(d1 / d2));
            char         text[60];
            if (p >= min_order)
              {
                e = std::abs(d2) / (std::pow(2., p) - 1.);
                std::snprintf(text, sizeof(text), "richardson p=%.2f", p);
              }
            else
              std::snprintf(text,
                            sizeof(text),
                            "last change (order p=%.2f below %.1f)",
                            p,
                            min_order);
            how = text;
          }
      }
    // Newmark's average acceleration rule is second order in dt.
    const double e_time = std::abs(half - q[k]) / 3.;
    return {(e + e_time) / std::abs(half), how + " + dt/2"};
  }



  void
  ConvergedRun::write_outputs(const Level &final_run)
  {
    SummaryWriter out;
    for (const auto &[key, value] : summary_entries)
      out.add_text(key, value);
    out.add_scientific("accuracy_tolerance", parameters.accuracy.tolerance);
    out.add_text("converged_contact_refinement_levels",
                 std::to_string(final_run.levels));
    out.add("converged_time_step_us", final_run.time_step * 1e6, 4);
    std::ostringstream log;
    log << "Accuracy = converged: error estimates";
    const std::vector<Quantity> all = quantities_of(final_run.results);
    for (const Quantity &q : all)
      {
        std::vector<double> values;
        for (const Level &level : sequence)
          values.push_back(q.value(level.results));
        auto [error, how] = estimate(values, q.value(final_run.results));
        if (!q.steers)
          how += "; on the contact surface, not converged";
        out.add_scientific(q.key + "_error_estimate", error);
        out.add_text(q.key + "_error_method", how);
        log << (&q == &all.front() ? ": " : ", ") << q.key << ' '
            << percent(error) << " (" << how << ")";
      }
    pcout << log.str() << '\n';
    summary.write(out);

    // convergence.csv: every run, the final one last.
    std::ostringstream csv;
    csv << "run,contact_refinement_levels,time_step_us,n_dofs,"
           "element_size_under_ball_mm";
    for (const Quantity &q : all)
      csv << ',' << q.column;
    csv << ",wall_time_s\n";
    std::vector<Level> rows = sequence;
    rows.push_back(final_run);
    for (std::size_t i = 0; i < rows.size(); ++i)
      {
        const Level &r = rows[i];
        char         line[200];
        std::snprintf(line,
                      sizeof(line),
                      "%zu,%u,%.4f,%u,%.6f",
                      i + 1,
                      r.levels,
                      r.time_step * 1e6,
                      r.results.n_dofs,
                      r.results.model.element_size_under_ball * 1e3);
        csv << line;
        for (const Quantity &q : all)
          {
            std::snprintf(line,
                          sizeof(line),
                          ",%.10g",
                          q.scale * q.value(r.results));
            csv << line;
          }
        std::snprintf(line, sizeof(line), ",%.3f\n", r.wall_time);
        csv << line;
      }
    run_on_root(communicator, [&]() {
      write_file_atomically(parameters.output.directory + "/convergence.csv",
                            csv.str());
    });
  }



  const ImpactResults &
  ConvergedRun::results() const
  {
    return final_results;
  }
} // namespace fgimpact
