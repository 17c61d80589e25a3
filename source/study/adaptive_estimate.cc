// Geometry/Adaptive refinement estimate: the check runs of an adaptive
// run's final mesh, one per source of error, and the estimates from them.

#include <deal.II/base/timer.h>

#include <fgimpact/base/exceptions.h>
#include <fgimpact/base/files.h>
#include <fgimpact/output/output_directory.h>
#include <fgimpact/study/adaptive_run.h>
#include <fgimpact/study/converged_run.h>
#include <fgimpact/study/simulator.h>

#include <cmath>
#include <cstdio>
#include <malloc.h>
#include <sstream>

namespace fgimpact
{
  std::string
  AdaptiveRun::check_name(const unsigned int check)
  {
    static const std::array<std::string, n_checks> names = {
      {"contact_zone", "rest_of_plate", "time_step"}};
    AssertIndexRange(check, n_checks);
    return names[check];
  }



  double
  AdaptiveRun::two_grid_estimate(const double coarse,
                                 const double fine,
                                 const double order)
  {
    const double r_p = std::pow(2., order);
    return two_grid_safety_factor * std::abs(fine - coarse) * r_p / (r_p - 1.) /
           std::abs(coarse);
  }



  void
  AdaptiveRun::run_checks()
  {
    // The sequence's outputs first: they are complete whatever the checks
    // do.  A check that fails or is interrupted then marks summary.txt
    // failed or interrupted (as the exit code says), naming the check; the
    // final run's numbers stay, without an estimate.
    write_outputs();
    try
      {
        for (unsigned int check = 0; check < n_checks; ++check)
          checks.push_back(run_check(check));
      }
    catch (const RunInterrupted &)
      {
        write_outputs("interrupted");
        throw;
      }
    catch (...)
      {
        write_outputs("failed");
        throw;
      }
  }



  AdaptiveRun::Run
  AdaptiveRun::run_check(const unsigned int check)
  {
    Parameters p     = parameters_of("adaptive_check_" + check_name(check));
    MeshSplit  split = MeshSplit::none;
    if (check == contact_zone)
      split = MeshSplit::contact_zone;
    else if (check == rest_of_plate)
      split = MeshSplit::rest_of_plate;
    else
      p.time_integration.time_step /= 2.;
    Timer timer;
    Run   run;
    try
      {
        Simulator simulator(p, communicator);
        simulator.set_adaptive_mesh(refined, split);
        simulator.setup();
        run_on_root(communicator,
                    [&]() { prepare_output_directory(p.output); });
        simulator.run();
        run.results   = simulator.get_results();
        run.n_cells   = simulator.n_active_cells();
        run.time_step = p.time_integration.time_step;
      }
    catch (...)
      {
        // The check's own line names its step and entry; without this
        // prefix it would read as the final run's, whose outputs are
        // complete.
        const std::exception_ptr failure = std::current_exception();
        try
          {
            std::rethrow_exception(failure);
          }
        catch (const ExcOutputFailure &)
          {
            throw; // names its file already
          }
        catch (...)
          {
            // A signal (RunInterrupted: run() names the check) or bad
            // input stays as it is.
            if (!is_run_failure(failure))
              throw;
          }
        throw ExcNumericalFailure(
          "Geometry/Adaptive refinement estimate, check " + check_name(check) +
          " (the final run's outputs are complete, without the estimate): " +
          failure_message(failure));
      }
    malloc_trim(0); // the freed heap back to the system before the next run
    run.wall_time = timer.wall_time();
    pcout << "Adaptive mesh: estimate's check " << check_name(check) << " on "
          << run.n_cells << " cells, " << run.results.n_dofs << " DoFs, step "
          << run.time_step * 1e6 << " us (" << p.output.directory
          << "): peak force " << run.results.peak_contact_force << " N\n";
    return run;
  }



  std::vector<std::array<double, AdaptiveRun::n_checks>>
  AdaptiveRun::estimates() const
  {
    // The final run is the coarser of each pair. Assumed orders: 1 for
    // the 8-node brick's mesh (its energy-norm order; the contact's
    // kinks make the point quantities no better), 2 for Newmark's
    // average acceleration rule.
    const std::array<double, n_checks>        order     = {{1., 1., 2.}};
    const ImpactResults                      &final_run = runs.back().results;
    std::vector<std::array<double, n_checks>> parts;
    for (const auto &q : ConvergedRun::quantities_of(parameters, final_run))
      {
        std::array<double, n_checks> part;
        for (unsigned int c = 0; c < n_checks; ++c)
          part[c] = two_grid_estimate(q.value(final_run),
                                      q.value(checks[c].results),
                                      order[c]);
        parts.push_back(part);
      }
    return parts;
  }



  void
  AdaptiveRun::write_estimates(SummaryWriter &out) const
  {
    // The headline numbers and the probes' peak stresses; one on the
    // contact surface is reported, not in the largest (as Accuracy =
    // converged does: ConvergedRun::quantities_of()).
    const auto quantities =
      ConvergedRun::quantities_of(parameters, runs.back().results);
    const auto         parts   = estimates();
    double             largest = 0, wall_time = 0;
    std::ostringstream log;
    log << "Adaptive mesh: error estimates (contact zone + rest of plate + "
           "time step)";
    for (std::size_t i = 0; i < quantities.size(); ++i)
      {
        const std::string &key   = quantities[i].key;
        double             total = 0;
        for (const double part : parts[i])
          total += part;
        if (quantities[i].steers)
          largest = std::max(largest, total);
        out.add_scientific(key + "_error_estimate", total);
        for (unsigned int c = 0; c < n_checks; ++c)
          out.add_scientific(key + "_error_estimate_" + check_name(c),
                             parts[i][c]);
        log << (i == 0 ? ": " : ", ") << key << ' '
            << ConvergedRun::percent(total) << " ("
            << ConvergedRun::percent(parts[i][0]) << " + "
            << ConvergedRun::percent(parts[i][1]) << " + "
            << ConvergedRun::percent(parts[i][2]) << ")";
      }
    out.add_scientific("largest_error_estimate", largest);
    for (const Run &check : checks)
      wall_time += check.wall_time;
    out.add("adaptive_estimate_wall_time_s", wall_time, 3);
    pcout << log.str() << '\n';
  }



  void
  AdaptiveRun::write_checks_csv() const
  {
    std::ostringstream csv;
    const auto         quantities =
      ConvergedRun::quantities_of(parameters, runs.back().results);
    csv << "run,n_cells,n_dofs,time_step_us";
    for (const auto &q : quantities)
      csv << ',' << q.column;
    csv << ",wall_time_s\n";
    for (unsigned int c = 0; c <= n_checks; ++c)
      {
        // The final run first: the coarser run of every pair.
        const Run &r = c == 0 ? runs.back() : checks[c - 1];
        char       line[200];
        std::snprintf(line,
                      sizeof(line),
                      "%s,%u,%u,%.6g",
                      c == 0 ? "final" : check_name(c - 1).c_str(),
                      r.n_cells,
                      r.results.n_dofs,
                      r.time_step * 1e6);
        csv << line << ConvergedRun::csv_values(quantities, r.results);
        std::snprintf(line, sizeof(line), ",%.3f\n", r.wall_time);
        csv << line;
      }
    run_on_root(communicator, [&]() {
      write_file_atomically(parameters.output.directory +
                              "/adaptive_estimate.csv",
                            csv.str());
    });
  }
} // namespace fgimpact
