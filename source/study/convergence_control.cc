// Accuracy = converged, its control: the sequence of steps, each number's
// estimate per source, and the one more refinement of the source with the
// largest share while a number's estimates add up to more than the
// tolerance (the runs are in converged_run.cc, the report in
// convergence_estimates.cc).

#include <fgimpact/base/exceptions.h>
#include <fgimpact/study/converged_run.h>

#include <algorithm>
#include <cmath>

namespace fgimpact
{
  namespace
  {
    /// The final run's time step at most Time step / 2^max_time_halvings:
    /// a time-step estimate still above the tolerance there is not one
    /// halving more can fix at a sane cost.
    constexpr unsigned int max_time_halvings = 5;
  } // namespace



  std::string
  ConvergedRun::source_name(const unsigned int source)
  {
    static const char *names[n_sources] = {"contact_levels",
                                           "base_mesh_in_plane",
                                           "base_mesh_thickness",
                                           "time_step"};
    return names[source];
  }



  void
  ConvergedRun::run_sequence()
  {
    // Each source changed by less than the tolerance at its last
    // refinement does not bound the sum: the default scene at 2 % had
    // its mid-plane deflection's estimates add up to 4.1 % (2.1 % in
    // plane, 1.8 % through the thickness).  The sum is checked before the
    // final run with the time step's share of the last final run, and
    // after it with its own.
    const double tolerance = parameters.accuracy.tolerance;
    run_input_levels();
    change_tolerance.fill(tolerance);
    for (;;)
      {
        refine_base_mesh();
        // A time step's share is made smaller by the final run itself.
        const Worst before = worst_sum(nullptr);
        if (before.total > tolerance && before.source != time_step)
          {
            refine_source(before, nullptr);
            continue;
          }
        const Level final_run = run_final();
        const Worst after     = worst_sum(&final_run);
        if (after.total <= tolerance)
          {
            write_outputs(final_run);
            return;
          }
        refine_source(after, &final_run);
      }
  }



  std::array<double, ConvergedRun::n_sources>
  ConvergedRun::parts_of(const Quantity &q, const Level *final_run) const
  {
    const auto values_of = [&q](const std::vector<Level> &runs) {
      std::vector<double> values;
      for (const Level &run : runs)
        values.push_back(q.value(run.results));
      return values;
    };
    const std::vector<double> levels = values_of(contact_chain),
                              plane  = values_of(in_plane_chain),
                              thick  = values_of(thickness_chain);
    const double value =
      final_run ? q.value(final_run->results) : levels[levels.size() - 2];
    std::array<double, n_sources> parts = {
      {coarser_error(levels), coarser_error(plane), coarser_error(thick), 0.}};
    for (double &part : parts)
      part *= safety_factor / std::abs(value);
    if (!final_run)
      {
        const auto last  = last_time_part.find(q.key);
        parts[time_step] = last == last_time_part.end() ? 0. : last->second;
        return parts;
      }
    // |q(dt/2^k) - q(dt/2^(k-1))| / 3 (Richardson, second order): at k = 1
    // against the contact chain's run the final one repeats at dt, else
    // against the final run before at twice the step.
    double reference = levels[levels.size() - 2];
    for (const Level &run : time_chain)
      if (run.levels == final_run->levels &&
          mesh_name(run.base) == mesh_name(final_run->base) &&
          std::abs(run.time_step / final_run->time_step - 2.) < 1e-9)
        reference = q.value(run.results);
    parts[time_step] =
      safety_factor * std::abs(value - reference) / 3. / std::abs(value);
    return parts;
  }



  ConvergedRun::Worst
  ConvergedRun::worst_sum(const Level *final_run) const
  {
    const ImpactResults &r = final_run ?
                               final_run->results :
                               contact_chain[contact_chain.size() - 2].results;
    Worst                worst;
    for (const Quantity &q : quantities_of(r))
      {
        if (!q.steers)
          continue;
        const auto   parts = parts_of(q, final_run);
        const double total = parts[0] + parts[1] + parts[2] + parts[3];
        if (total <= worst.total)
          continue;
        const auto largest = std::max_element(parts.begin(), parts.end());
        worst              = {total,
                              q.key,
                              static_cast<unsigned int>(largest - parts.begin()),
                              *largest};
      }
    return worst;
  }



  void
  ConvergedRun::refine_source(const Worst &worst, const Level *final_run)
  {
    // The final run made is no longer the last word: a failure from here
    // on is the sequence's (Simulator writes the failed summary.txt).
    final_started = false;
    const std::string sum =
      "Accuracy = converged: the estimates of " + worst.key + " add up to " +
      percent(worst.total) +
      ", above Accuracy tolerance = " + percent(parameters.accuracy.tolerance) +
      ", " + percent(worst.part) + " of it from " + source_name(worst.source);
    if (final_run)
      for (const Quantity &q : quantities_of(final_run->results))
        last_time_part[q.key] = parts_of(q, final_run)[time_step];
    if (worst.source == time_step)
      {
        AssertThrow(time_halvings < max_time_halvings,
                    ExcMessage(sum + " at Time step / " +
                               std::to_string(1u << time_halvings) +
                               "; lower Time integration/Time step or "
                               "raise Accuracy tolerance."));
        time_chain.push_back(*final_run);
        ++time_halvings;
        pcout << sum << ": the final run again at half its time step\n";
        return;
      }
    // One more refinement of that source at least: its chain stops at its
    // first change below its last one.
    const std::vector<Level> &chain =
      worst.source == contact_levels ? contact_chain :
      worst.source == in_plane       ? in_plane_chain :
                                       thickness_chain;
    change_tolerance[worst.source] =
      std::min(change_tolerance[worst.source],
               largest_change(chain[chain.size() - 2].results,
                              chain.back().results)
                 .first);
    pcout << sum << ": refined once more (change tolerance "
          << percent(change_tolerance[worst.source]) << ")\n";
  }
} // namespace fgimpact
