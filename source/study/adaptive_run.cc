// Geometry/Adaptive refinement cycles: the pilot runs whose indicator
// refines the mesh, the final run, adaptation.csv and the summary's keys.

#include <deal.II/base/timer.h>

#include <fgimpact/base/exceptions.h>
#include <fgimpact/base/files.h>
#include <fgimpact/output/output_directory.h>
#include <fgimpact/problem/resources.h>
#include <fgimpact/problem/scene.h>
#include <fgimpact/study/adaptive_run.h>
#include <fgimpact/study/converged_run.h>
#include <fgimpact/study/simulator.h>

#include <cmath>
#include <cstdio>
#include <malloc.h>
#include <sstream>

namespace fgimpact
{
  AdaptiveRun::AdaptiveRun(
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



  AdaptiveRun::~AdaptiveRun() = default;



  Parameters
  AdaptiveRun::parameters_of(const std::string &name) const
  {
    Parameters p               = parameters;
    p.geometry.adaptive_cycles = 0; // the runs themselves are plain ones
    // No checkpoints: the sequence cannot be resumed (--resume refuses it).
    p.output.checkpoint_interval = 0;
    if (name.empty())
      return p;
    p.output.directory = parameters.output.directory + "/convergence/" + name;
    p.output.vtu_interval   = 0;
    p.output.snapshot_times = {};
    p.output.peak_snapshot  = false;
    return p;
  }



  void
  AdaptiveRun::setup()
  {
    // The first pilot run's set-up checks the input (the mesh included)
    // before anything is written.
    first = std::make_unique<Simulator>(parameters_of("adaptive_cycle_0"),
                                        communicator);
    first->record_refinement_indicator();
    first->setup();
    // Each cycle splits ceil(fraction n) cells into eight: the final mesh
    // has about (1 + 7 fraction)^N times the input's cells (p4est's
    // balance adds a few: 14,828 for 14,808 on the default scene).
    const auto  &g = parameters.geometry;
    const double final_cells =
      first->n_active_cells() *
      std::pow(1. + 7. * g.adaptive_fraction, g.adaptive_cycles);
    check_fits(final_cells, "the final mesh, expected");
    // The rest_of_plate check splits nearly every cell of it.
    if (g.adaptive_estimate)
      check_fits(8. * final_cells, "its estimate's rest_of_plate check");
  }



  void
  AdaptiveRun::check_fits(const double n_cells, const std::string &what) const
  {
    const Parameters p = parameters_of("");
    ResourceEstimate e =
      estimate_resources(p, contact_refinement_of(p, scene_without_mesh(p)));
    const double ratio = n_cells / e.n_cells;
    for (double *linear : {&e.n_cells,
                           &e.n_dofs,
                           &e.matrix_nnz,
                           &e.mesh,
                           &e.matrices,
                           &e.vectors,
                           &e.output})
      *linear *= ratio;
    e.factor_nnz *= std::pow(ratio, 4. / 3.);
    e.factor *= std::pow(ratio, 4. / 3.);
    try
      {
        check_memory(p, e, communicator);
      }
    catch (const ExceptionBase &error)
      {
        char fraction[32];
        std::snprintf(fraction,
                      sizeof(fraction),
                      "%g",
                      parameters.geometry.adaptive_fraction);
        AssertThrow(false,
                    ExcMessage(
                      "Geometry/Adaptive refinement cycles = " +
                      std::to_string(parameters.geometry.adaptive_cycles) +
                      " with fraction " + fraction + ": " + what + " (" +
                      std::to_string(std::llround(n_cells)) +
                      " cells) does not fit; lower the cycles or "
                      "the fraction: " +
                      message_of(error)));
      }
  }



  void
  AdaptiveRun::run_pilot(const unsigned int cycle)
  {
    const Parameters p =
      parameters_of("adaptive_cycle_" + std::to_string(cycle));
    Timer                      timer;
    std::unique_ptr<Simulator> simulator = std::move(first);
    if (!simulator)
      {
        check_fits(runs.back().n_cells + 7. * runs.back().n_refined,
                   "the mesh of cycle " + std::to_string(cycle + 1));
        simulator = std::make_unique<Simulator>(p, communicator);
        simulator->set_adaptive_mesh(refined);
        simulator->record_refinement_indicator();
        simulator->setup();
      }
    run_on_root(communicator, [&]() { prepare_output_directory(p.output); });
    simulator->run();
    Run run;
    run.results   = simulator->get_results();
    run.n_cells   = simulator->n_active_cells();
    run.time_step = p.time_integration.time_step;
    refined.push_back(simulator->refinement_indicator().cells_to_refine(
      parameters.geometry.adaptive_fraction));
    run.n_refined = refined.back().size();
    simulator.reset();
    malloc_trim(0); // the freed heap back to the system before the next run
    run.wall_time = timer.wall_time();
    pcout << "Adaptive mesh: cycle " << cycle + 1 << " of "
          << parameters.geometry.adaptive_cycles << " on " << run.n_cells
          << " cells, " << run.results.n_dofs << " DoFs (" << p.output.directory
          << "): peak force " << run.results.peak_contact_force
          << " N; refining the " << run.n_refined
          << " cells of largest indicator\n";
    runs.push_back(run);
  }



  void
  AdaptiveRun::run_final()
  {
    check_fits(runs.back().n_cells + 7. * runs.back().n_refined,
               "the final mesh");
    const Parameters p = parameters_of("");
    Timer            timer;
    Simulator        simulator(p, communicator);
    simulator.set_adaptive_mesh(refined);
    for (const auto &observer : observers)
      simulator.add_history_observer(observer);
    simulator.setup();
    pcout << "Adaptive mesh: the final run on " << simulator.n_active_cells()
          << " cells, into " << parameters.output.directory << '\n';
    final_started = true;
    simulator.run();
    Run run;
    run.results     = simulator.get_results();
    run.n_cells     = simulator.n_active_cells();
    run.time_step   = p.time_integration.time_step;
    run.wall_time   = timer.wall_time();
    summary_entries = simulator.summary().entries();
    runs.push_back(run);
  }



  void
  AdaptiveRun::run()
  {
    const unsigned int cycles = parameters.geometry.adaptive_cycles;
    try
      {
        for (unsigned int cycle = 0; cycle < cycles; ++cycle)
          run_pilot(cycle);
        run_final();
        if (parameters.geometry.adaptive_estimate)
          run_checks();
      }
    catch (const RunInterrupted &e)
      {
        // A pilot's own message offers --resume of its directory, which
        // would finish that one run, not the sequence.
        throw RunInterrupted(
          e.signal,
          "Adaptive mesh interrupted by signal " + std::to_string(e.signal) +
            (runs.size() > cycles ?
               " in the error estimate's check " + check_name(checks.size()) :
             final_started ?
               " in the final run" :
               " in pilot cycle " + std::to_string(runs.size() + 1) + " of " +
                 std::to_string(cycles)) +
            ": the sequence cannot be resumed (--resume refuses it); run "
            "the same command again.");
      }
    write_outputs();
  }



  void
  AdaptiveRun::write_outputs(const std::string &status) const
  {
    const auto   &quantities = ConvergedRun::quantities();
    SummaryWriter out;
    for (const auto &[key, value] : summary_entries)
      out.add_text(key, key == "status" && !status.empty() ? status : value);
    if (!status.empty())
      out.add_text("adaptive_estimate_stopped_in_check",
                   check_name(checks.size()));
    out.add_text("adaptive_refinement_cycles",
                 std::to_string(parameters.geometry.adaptive_cycles));
    out.add("adaptive_refinement_fraction",
            parameters.geometry.adaptive_fraction,
            3);
    // wall_time_s above is the final run's; the pilots' come on top.
    double sequence = 0;
    for (const Run &run : runs)
      sequence += run.wall_time;
    out.add("adaptive_sequence_wall_time_s", sequence, 3);
    std::ostringstream log;
    log << "Adaptive mesh: change from the last pilot run to the final one";
    const ImpactResults &a = runs[runs.size() - 2].results,
                        &b = runs.back().results;
    for (const auto &q : quantities)
      {
        const double change =
          std::abs(q.value(b) - q.value(a)) / std::abs(q.value(b));
        out.add_scientific(q.key + "_change_last_adaptive_cycle", change);
        log << (&q == &quantities.front() ? ": " : ", ") << q.key << ' '
            << ConvergedRun::percent(change);
      }
    // Logged once: before the estimate's checks (or without them).
    const bool estimated = checks.size() == n_checks;
    if (estimated)
      write_estimates(out);
    else if (status.empty())
      pcout << log.str() << '\n';
    summary.write(out);
    write_csv();
    if (estimated)
      write_checks_csv();
  }



  void
  AdaptiveRun::write_csv() const
  {
    const auto        &quantities = ConvergedRun::quantities();
    std::ostringstream csv;
    csv << "run,n_cells,n_dofs,element_size_under_ball_mm";
    for (const auto &q : quantities)
      csv << ',' << q.column;
    csv << ",refined_cells,wall_time_s\n";
    for (std::size_t i = 0; i < runs.size(); ++i)
      {
        const Run &r = runs[i];
        char       line[200];
        std::snprintf(line,
                      sizeof(line),
                      "%zu,%u,%u,%.6f",
                      i + 1,
                      r.n_cells,
                      r.results.n_dofs,
                      r.results.model.element_size_under_ball * 1e3);
        csv << line << ConvergedRun::csv_values(quantities, r.results);
        std::snprintf(
          line, sizeof(line), ",%u,%.3f\n", r.n_refined, r.wall_time);
        csv << line;
      }
    run_on_root(communicator, [&]() {
      write_file_atomically(parameters.output.directory + "/adaptation.csv",
                            csv.str());
    });
  }
} // namespace fgimpact
