// Accuracy = converged, its report: the numbers it steers by and their
// largest change, the error estimate of each number,
// one per discretization source, in summary.txt and the log, and
// convergence.csv (ConvergedRun's runs are in converged_run.cc).

#include <fgimpact/base/exceptions.h>
#include <fgimpact/base/files.h>
#include <fgimpact/study/converged_run.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

namespace fgimpact
{
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
      {"max_approach", "max_approach_um", 1e6, [](const ImpactResults &r) {
         return r.max_approach;
       }}};
    return q;
  }



  std::pair<double, std::string>
  ConvergedRun::largest_change() const
  {
    return largest_change(sequence[sequence.size() - 2].results,
                          sequence.back().results);
  }



  std::pair<double, std::string>
  ConvergedRun::largest_change(const ImpactResults &a,
                               const ImpactResults &b) const
  {
    std::pair<double, std::string> largest = {0., ""};
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



  std::string
  ConvergedRun::percent(const double relative)
  {
    // Three decimals (0.010 %), two digits below them (1e-6: 0.0001 %).
    char text[40];
    std::snprintf(text,
                  sizeof(text),
                  std::abs(relative) < 5e-6 && relative != 0. ? "%.2g %%" :
                                                                "%.3f %%",
                  100. * relative);
    return text;
  }



  std::pair<double, std::string>
  ConvergedRun::refinement_error(const std::vector<double> &q)
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
    return {e, how};
  }



  double
  ConvergedRun::coarser_error(const std::vector<double> &q)
  {
    // |q* - q[k-1]| <= |q[k] - q[k-1]| + |q* - q[k]|.
    return std::abs(q.back() - q[q.size() - 2]) + refinement_error(q).first;
  }



  ConvergedRun::Needed
  ConvergedRun::refinements_needed(const std::vector<Level> &chain) const
  {
    // With changes shrinking by 2^p per refinement, a change c falls below
    // the tolerance after log2(c / tolerance) / p more.  Changes that do
    // not shrink show no order yet (runs before the asymptotic range): no
    // prediction.
    Needed needed;
    if (chain.size() < 3)
      return needed;
    const double       tolerance = parameters.accuracy.tolerance;
    const unsigned int k         = chain.size() - 1;
    for (const Quantity &q : quantities_of(chain.back().results))
      {
        if (!q.steers)
          continue;
        const double a    = q.value(chain[k - 2].results),
                     b    = q.value(chain[k - 1].results),
                     c    = q.value(chain[k].results);
        const double last = std::abs(c - b) / std::abs(c);
        const double p    = std::log2(std::abs(b - a) / std::abs(c - b));
        if (!(last >= tolerance) || !(p > 0.))
          continue;
        const double more = std::ceil(std::log2(last / tolerance) / p);
        if (more > needed.more)
          needed = {more, q.key, last, p};
      }
    return needed;
  }



  std::string
  ConvergedRun::Needed::describe(const std::string &where) const
  {
    char text[300];
    std::snprintf(text,
                  sizeof(text),
                  "%s changed by %s %s with an observed order p = %.2f, and "
                  "the tolerance needs about %.0f more refinements",
                  key.c_str(),
                  percent(last).c_str(),
                  where.c_str(),
                  p,
                  more);
    return text;
  }



  void
  ConvergedRun::refuse_unreachable(const std::vector<Level> &chain,
                                   const std::string        &name,
                                   const unsigned int        room) const
  {
    // More doublings than the factor of 16 allows (room: the doublings
    // left, as a factor): the runs before the limit are spent for nothing
    // (the default scene's probes at 1 %: 2.7 min and 6.3 GB of the 4.5
    // min).
    const Needed needed = refinements_needed(chain);
    if (needed.more == 0. || std::pow(2., needed.more) <= room)
      return;
    AssertThrow(
      false,
      ExcMessage(
        "Accuracy tolerance = " + percent(parameters.accuracy.tolerance) +
        " cannot be reached (" + name +
        "): " + needed.describe("on " + mesh_name(chain.back().base)) +
        ", beyond the 16-fold limit of Geometry/Subdivisions; raise "
        "Accuracy tolerance to at least " +
        percent(needed.last / std::pow(std::max(room, 1u), needed.p)) +
        ", or leave the number out (a probe: Output/Probe points)."));
  }



  void
  ConvergedRun::write_outputs(const Level &final_run)
  {
    // The estimates first: a sum above the tolerance is a warning of the
    // run, in summary.txt's warnings as in the log (it said none).
    SummaryWriter     estimates;
    const double      largest   = write_estimates(estimates, final_run);
    const double      tolerance = parameters.accuracy.tolerance;
    const std::string exceeded =
      largest > tolerance ?
        "the largest error estimate, " + percent(largest) +
          ", exceeds Accuracy tolerance, " + percent(tolerance) +
          ": each source changed by less than the tolerance at its last "
          "refinement, and their estimates add up to more" :
        std::string();
    SummaryWriter out;
    for (const auto &[key, value] : summary_entries)
      out.add_text(key,
                   key != "warnings" || exceeded.empty() ? value :
                   value == "none"                       ? exceeded :
                                     value + "; " + exceeded);
    out.add_scientific("accuracy_tolerance", parameters.accuracy.tolerance);
    out.add_text("converged_contact_refinement_levels",
                 std::to_string(final_run.levels));
    out.add_text("converged_base_mesh", mesh_name(final_run.base));
    out.add("converged_time_step_us", final_run.time_step * 1e6, 4);
    // The runs each source's estimate is made from, as
    // convergence.csv's rows: "NXxNYxNZ/L" each.
    const auto runs = [this](const std::vector<Level> &chain) {
      std::string text;
      for (const Level &run : chain)
        text += (text.empty() ? "" : " ") + mesh_name(run.base) + "/" +
                std::to_string(run.levels);
      return text;
    };
    out.add_text("error_estimate_runs_contact_levels", runs(contact_chain));
    out.add_text("error_estimate_runs_base_mesh_in_plane",
                 runs(in_plane_chain));
    out.add_text("error_estimate_runs_base_mesh_thickness",
                 runs(thickness_chain));
    for (const auto &[key, value] : estimates.entries())
      out.add_text(key, value);
    summary.write(out);
    write_csv(final_run);
  }



  double
  ConvergedRun::write_estimates(SummaryWriter &out,
                                const Level   &final_run) const
  {
    std::ostringstream log;
    log << "Accuracy = converged: error estimates (contact levels + in "
           "plane + thickness + time step)";
    const std::vector<Quantity> all     = quantities_of(final_run.results);
    double                      largest = 0;
    for (const Quantity &q : all)
      {
        const auto values_of = [&q](const std::vector<Level> &runs) {
          std::vector<double> values;
          for (const Level &run : runs)
            values.push_back(q.value(run.results));
          return values;
        };
        const std::vector<double> plane = values_of(in_plane_chain),
                                  thick = values_of(thickness_chain);
        const double half               = q.value(final_run.results);
        // The final run at dt/2 repeats the contact chain's second-to-last
        // run at dt.
        const std::vector<double> levels = values_of(contact_chain);
        const double parts[4] = {coarser_error(levels) / std::abs(half),
                                 coarser_error(plane) / std::abs(half),
                                 coarser_error(thick) / std::abs(half),
                                 std::abs(half - levels[levels.size() - 2]) /
                                   3. / std::abs(half)};
        const double total    = parts[0] + parts[1] + parts[2] + parts[3];
        std::string  method =
          "runs per chain: " + std::to_string(levels.size()) +
          " contact levels, " + std::to_string(plane.size()) +
          " base meshes in plane, " + std::to_string(thick.size()) +
          " through the thickness; + dt/2";
        if (!q.steers)
          method += "; on the contact surface, not converged";
        else
          largest = std::max(largest, total);
        out.add_scientific(q.key + "_error_estimate", total);
        const char *sources[4] = {"contact_levels",
                                  "base_mesh_in_plane",
                                  "base_mesh_thickness",
                                  "time_step"};
        for (unsigned int s = 0; s < 4; ++s)
          out.add_scientific(q.key + "_error_estimate_" + sources[s], parts[s]);
        out.add_text(q.key + "_error_method", method);
        log << (&q == &all.front() ? ": " : ", ") << q.key << ' '
            << percent(total) << " (" << percent(parts[0]) << " + "
            << percent(parts[1]) << " + " << percent(parts[2]) << " + "
            << percent(parts[3]) << ")";
      }
    pcout << log.str() << '\n';
    out.add_scientific("largest_error_estimate", largest);
    if (largest > parameters.accuracy.tolerance)
      pcout << "  WARNING: the largest error estimate, " << percent(largest)
            << ", exceeds Accuracy tolerance = "
            << percent(parameters.accuracy.tolerance)
            << ": each source changed by less than the tolerance at its "
               "last refinement, and their estimates add up to more.\n";
    return largest;
  }



  void
  ConvergedRun::write_csv(const Level &final_run) const
  {
    const std::vector<Quantity> all = quantities_of(final_run.results);
    std::ostringstream          csv;
    csv << "run,contact_refinement_levels,subdivisions_x,subdivisions_y,"
           "subdivisions_z,time_step_us,n_dofs,element_size_under_ball_mm";
    for (const Quantity &q : all)
      csv << ',' << q.column;
    csv << ",wall_time_s\n";
    // In the order run: the contact levels on the input's mesh, the base
    // meshes and the contact levels on the final base, the final run.
    std::vector<Level> rows = sequence;
    rows.insert(rows.end(), refinement_runs.begin(), refinement_runs.end());
    rows.push_back(final_run);
    const auto &g = parameters.geometry;
    for (std::size_t i = 0; i < rows.size(); ++i)
      {
        const Level &r = rows[i];
        char         line[200];
        std::snprintf(line,
                      sizeof(line),
                      "%zu,%u,%u,%u,%u,%.4f,%u,%.6f",
                      i + 1,
                      r.levels,
                      g.subdivisions_x * r.base.in_plane,
                      g.subdivisions_y * r.base.in_plane,
                      g.subdivisions_z * r.base.thickness,
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
} // namespace fgimpact
