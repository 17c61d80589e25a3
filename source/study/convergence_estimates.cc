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



  std::string
  ConvergedRun::csv_values(const std::vector<Quantity> &quantities,
                           const ImpactResults         &r)
  {
    std::string text;
    for (const Quantity &q : quantities)
      {
        char value[40];
        std::snprintf(value, sizeof(value), ",%.10g", q.scale * q.value(r));
        text += value;
      }
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
  ConvergedRun::refinements_needed(const std::vector<Level> &chain,
                                   const double              tolerance) const
  {
    // With changes shrinking by 2^p per refinement, a change c falls below
    // the tolerance after log2(c / tolerance) / p more.  Changes that do
    // not shrink show no order yet (runs before the asymptotic range): no
    // prediction.
    Needed needed;
    if (chain.size() < 3)
      return needed;
    const unsigned int k = chain.size() - 1;
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
                                   const unsigned int        room,
                                   const double              tolerance) const
  {
    // More doublings than the factor of 16 allows (room: the doublings
    // left, as a factor): the runs before the limit are spent for nothing
    // (the default scene's probes at 1 %: 2.7 min and 6.3 GB of the 4.5
    // min).
    const Needed needed = refinements_needed(chain, tolerance);
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
    // The sums are below the tolerance here (run_sequence() stops only
    // then, or refuses).
    SummaryWriter estimates;
    write_estimates(estimates, final_run);
    SummaryWriter out;
    for (const auto &[key, value] : summary_entries)
      out.add_text(key, value);
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
    // Each source's change tolerance after the control of the sum (its
    // chain stopped at its first change below it).
    for (unsigned int s = 0; s < time_step; ++s)
      out.add_scientific("change_tolerance_" + source_name(s),
                         change_tolerance[s]);
    out.add_text("converged_time_step_fraction",
                 "1/" + std::to_string(1u << time_halvings));
    for (const auto &[key, value] : estimates.entries())
      out.add_text(key, value);
    summary.write(out);
    write_csv(final_run);
  }



  void
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
        const auto   parts = parts_of(q, &final_run);
        const double total = parts[0] + parts[1] + parts[2] + parts[3];
        std::string  method =
          "runs per chain: " + std::to_string(contact_chain.size()) +
          " contact levels, " + std::to_string(in_plane_chain.size()) +
          " base meshes in plane, " + std::to_string(thickness_chain.size()) +
          " through the thickness; + dt/" + std::to_string(1u << time_halvings);
        if (!q.steers)
          method += "; on the contact surface, not converged";
        else
          largest = std::max(largest, total);
        out.add_scientific(q.key + "_error_estimate", total);
        for (unsigned int s = 0; s < n_sources; ++s)
          out.add_scientific(q.key + "_error_estimate_" + source_name(s),
                             parts[s]);
        out.add_text(q.key + "_error_method", method);
        log << (&q == &all.front() ? ": " : ", ") << q.key << ' '
            << percent(total) << " (" << percent(parts[0]) << " + "
            << percent(parts[1]) << " + " << percent(parts[2]) << " + "
            << percent(parts[3]) << ")";
      }
    pcout << log.str() << '\n';
    out.add_scientific("largest_error_estimate", largest);
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
    // meshes and the contact levels, the final runs at the coarser time
    // steps on the final mesh (their files replaced by the final run's),
    // the final run.
    std::vector<Level> rows = sequence;
    rows.insert(rows.end(), refinement_runs.begin(), refinement_runs.end());
    rows.insert(rows.end(), time_chain.begin(), time_chain.end());
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
        csv << line << csv_values(all, r.results);
        std::snprintf(line, sizeof(line), ",%.3f\n", r.wall_time);
        csv << line;
      }
    run_on_root(communicator, [&]() {
      write_file_atomically(parameters.output.directory + "/convergence.csv",
                            csv.str());
    });
  }
} // namespace fgimpact
