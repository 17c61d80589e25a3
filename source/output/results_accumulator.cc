// The postprocessors that watch the time history without writing files:
// the results (peak, episodes, maxima), the energy watchdog and the
// screen log.

#include <deal.II/base/exceptions.h>

#include <fgimpact/base/exceptions.h>
#include <fgimpact/output/impact_summary.h>
#include <fgimpact/output/postprocessors.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace fgimpact
{
  namespace
  {
    /// The results that the time history accumulates, in a fixed order
    /// (the set-up's entries are computed anew on resume).
    template <typename Apply>
    void
    history_results(const Apply &archive, ImpactResults &r)
    {
      for (auto *value : {&r.peak_contact_force,
                          &r.max_sampled_force,
                          &r.time_of_peak_force,
                          &r.contact_duration,
                          &r.max_indentation,
                          &r.max_approach,
                          &r.max_contact_radius,
                          &r.max_contact_pressure,
                          &r.max_midplane_deflection,
                          &r.max_top_deflection,
                          &r.impulse,
                          &r.max_energy_drift})
        archive(*value);
      for (auto *value : {&r.max_contact_nodes,
                          &r.n_impacts,
                          &r.max_newton_iterations,
                          &r.max_linear_iterations})
        archive(*value);
      archive(r.linear_iterations);
    }
  } // namespace



  ResultsAccumulator::ResultsAccumulator(ImpactResults            &results,
                                         const ContactModel       &contact,
                                         const double              m,
                                         const double              V0,
                                         const double              dt,
                                         const bool                symmetric,
                                         const ConditionalOStream &pcout)
    : results(results)
    , contact_model(contact)
    , m(m)
    , V0(V0)
    , dt(dt)
    , symmetric_part(symmetric)
    , pcout(pcout)
  {
    // A fresh run: the time history's entries start from nothing.
    ImpactResults &r     = results;
    r.peak_contact_force = r.max_sampled_force = 0;
    r.time_of_peak_force = r.impulse = 0;
    r.max_indentation = r.max_approach = r.max_energy_drift = 0;
    r.max_contact_radius = r.max_contact_pressure = 0;
    r.max_contact_nodes                           = 0;
    r.max_midplane_deflection = r.max_top_deflection = 0;
    r.max_newton_iterations                          = 0;
    r.linear_iterations                              = 0;
    r.max_linear_iterations                          = 0;
    r.contact_duration = std::numeric_limits<double>::quiet_NaN();
    r.n_impacts        = 1;
  }



  void
  ResultsAccumulator::execute(const StepRecord &record)
  {
    const ContactState &contact = *record.sample->contact;
    if (record.step > 0)
      {
        // Trapezoidal impulse: consistent with both schemes' impactor
        // update, m (v_{n+1} - v_n) = -dt (F_n + F_{n+1})/2 for gamma = 1/2.
        results.impulse += 0.5 * dt * (last_force + contact.force);
        update_episodes(record.t, contact);
      }
    update_extremes(record.t, *record.sample);
    results.max_energy_drift =
      std::max(results.max_energy_drift, record.energy_drift);
    results.linear_iterations += record.linear_iterations;
    results.max_linear_iterations =
      std::max(results.max_linear_iterations, record.linear_iterations);
    last_force = contact.force;
    last_alpha = contact.alpha;
  }



  void
  ResultsAccumulator::update_episodes(const double        t,
                                      const ContactState &contact)
  {
    // Separation time by linear interpolation of the indentation's zero
    // crossing (second-order accurate).
    const bool now_in_contact = (contact.alpha > 0.);
    if (in_contact && !now_in_contact && !separated_once)
      {
        separated_once = true;
        results.contact_duration =
          t - dt + dt * last_alpha / (last_alpha - contact.alpha);
      }
    if (!in_contact && now_in_contact)
      ++results.n_impacts;
    in_contact = now_in_contact;
  }



  void
  ResultsAccumulator::update_extremes(const double         t,
                                      const HistorySample &sample)
  {
    ImpactResults &r = results;
    const double   F = sample.contact->force;
    peak_resolved    = false;
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
        peak_pending  = false;
        peak_resolved = true;
      }
    const ContactState &c = *sample.contact;
    r.max_indentation     = std::max(r.max_indentation, c.alpha);
    // The measured approach of ball and plate: the ball's displacement
    // minus the mid-plane's under the impact point (the Hertz law's
    // alpha in the impact literature; with a resolved contact it holds
    // the local compression and the crater, which (F/K)^{2/3} does not).
    r.max_approach = std::max(r.max_approach, sample.ball->w - sample.W_mid);
    r.max_contact_radius   = std::max(r.max_contact_radius, c.contact_radius);
    r.max_contact_pressure = std::max(r.max_contact_pressure, c.max_pressure);
    r.max_contact_nodes    = std::max(r.max_contact_nodes, c.n_active);
    r.max_midplane_deflection =
      std::max(r.max_midplane_deflection, sample.W_mid);
    r.max_top_deflection = std::max(r.max_top_deflection, sample.W_top);
    r.max_newton_iterations =
      std::max(r.max_newton_iterations, c.newton_iterations);
  }



  void
  ResultsAccumulator::save(CheckpointWriter &out, const unsigned int)
  {
    history_results([&out](const auto &value) { out.put(value); }, results);
    for (const double value : {last_force, last_alpha, peak_left})
      out.put(value);
    for (const bool flag : {in_contact, separated_once, peak_pending})
      out.put(flag);
  }



  void
  ResultsAccumulator::load(CheckpointReader &in)
  {
    history_results([&in](auto &value) { in.get(value); }, results);
    for (double *value : {&last_force, &last_alpha, &peak_left})
      in.get(*value);
    for (bool *flag : {&in_contact, &separated_once, &peak_pending})
      in.get(*flag);
  }



  void
  ResultsAccumulator::finish(const ImpactorState &ball)
  {
    ImpactResults &r = results;
    // The candidate set may have grown during the run.
    r.n_contact_candidates = contact_model.contact_dofs().size();
    // A symmetric part: the model counts the whole plate's candidates.
    if (symmetric_part)
      r.set_contact_constants(contact_model.constants());
    r.departure_velocity =
      in_contact ? std::numeric_limits<double>::quiet_NaN() : -ball.v;
    // int F dt = m (V0 + V_departure), with the ball's current velocity.
    r.impulse_identity_error =
      std::abs(r.impulse - m * (V0 - ball.v)) / (m * V0);

    if (in_contact || !separated_once)
      pcout << "  WARNING: the impactor is still in contact at the last time "
               "step; contact_duration and departure_velocity do not exist "
               "and are written as 'none' (raise Time integration/End "
               "time).\n";
    if (r.n_impacts > 1)
      pcout << "  note: the impactor struck the plate " << r.n_impacts
            << " times.\n";
    // After the run's own (a snapshot the automatic end left behind);
    // each once, should this be called again.
    for (const auto &warning :
         resolution_warnings(r, contact_model.reports_contact_area()))
      if (std::find(r.warnings.begin(), r.warnings.end(), warning) ==
          r.warnings.end())
        {
          r.warnings.push_back(warning);
          pcout << "  WARNING: " << warning << ".\n";
        }
  }



  EnergyWatchdog::EnergyWatchdog(const ConditionalOStream &pcout,
                                 const std::string        &advice)
    : pcout(pcout)
    , advice(advice)
  {}



  void
  EnergyWatchdog::execute(const StepRecord &record)
  {
    // Implicit Newmark conserves the discrete energy up to the contact's
    // quadrature error (1e-4..1e-3 on the paper's cases); 0.5 is far
    // beyond any accurate run, and NaN fails the test too.
    const double drift         = record.energy_drift;
    const double warning_level = 1e-2, stop_level = 0.5;
    char         where[100];
    std::snprintf(where,
                  sizeof(where),
                  "time step %u (t = %.3f us)",
                  record.step,
                  record.t * 1e6);
    if (!(drift <= stop_level))
      {
        char text[100];
        std::snprintf(text, sizeof(text), "%.3e", drift);
        AssertThrow(false,
                    ExcNumericalFailure(
                      std::string("the run is blowing up: the relative "
                                  "energy drift reached ") +
                      text + " (limit 0.5) at " + where + "; " + advice + "."));
      }
    if (drift > warning_level && !warned)
      {
        warned = true;
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
  EnergyWatchdog::save(CheckpointWriter &out, const unsigned int)
  {
    out.put(warned);
  }



  void
  EnergyWatchdog::load(CheckpointReader &in)
  {
    in.get(warned);
  }



  RunLog::RunLog(const unsigned int        log_interval,
                 const unsigned int        n_steps,
                 const double              E0,
                 const bool                progress,
                 const ConditionalOStream &pcout,
                 const unsigned int        expected_steps)
    : log_interval(log_interval)
    , n_steps(n_steps)
    , E0(E0)
    , pcout(pcout)
    , progress(n_steps, pcout.is_active() && progress, expected_steps)
  {}



  void
  RunLog::execute(const StepRecord &record)
  {
    report_lcp_fallback(record);
    const HistorySample &s = *record.sample;
    if (log_interval > 0 &&
        (record.step % log_interval == 0 || record.step == n_steps))
      {
        char line[200];
        std::snprintf(line,
                      sizeof(line),
                      "  step %6u  t = %9.3f us  F = %10.3f N  alpha = "
                      "%8.4f um  W_mid = %8.4f um  E/E0 - 1 = %+.2e\n",
                      record.step,
                      record.t * 1e6,
                      s.contact->force,
                      s.contact->alpha * 1e6,
                      s.W_mid * 1e6,
                      s.E_total / E0 - 1.);
        pcout << line;
      }
    progress.update(record.step, std::cout);
  }



  void
  RunLog::report_lcp_fallback(const StepRecord &record)
  {
    // Rare (PDAS settles in a few iterations for contact Delassus
    // matrices): say so once, with what the fallback left.
    const ContactState &contact = *record.part_contact;
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
                  record.step,
                  record.t * 1e6,
                  contact.residual_penetration * 1e6);
    pcout << line;
  }
} // namespace fgimpact
