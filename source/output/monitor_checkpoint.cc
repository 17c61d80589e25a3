// The ImpactMonitor's part of a checkpoint (the rest is in monitor.cc).

#include <fgimpact/app/run_control.h>
#include <fgimpact/output/monitor.h>

#include <sstream>

namespace fgimpact
{
  namespace
  {
    using Records = std::vector<std::pair<double, std::string>>;

    void
    put_records(CheckpointWriter &out, const Records &records)
    {
      out.put<std::uint64_t>(records.size());
      for (const auto &[t, name] : records)
        {
          out.put(t);
          out.put(name);
        }
    }

    void
    get_records(CheckpointReader &in, Records &records)
    {
      std::uint64_t n = 0;
      in.get(n);
      records.resize(n);
      for (auto &[t, name] : records)
        {
          in.get(t);
          in.get(name);
        }
    }

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



  void
  ImpactMonitor::save(CheckpointWriter &out, const unsigned int step)
  {
    std::uintmax_t length = 0, probes_length = 0;
    bool           in_flight = false;
    Records        vtu_now;
    try
      {
        if (history)
          length = history->length();
        if (probe_csv)
          probes_length = probe_csv->length();
        if (vtu)
          vtu_now = vtu->records(step, in_flight);
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
    history_results([&out](const auto &value) { out.put(value); },
                    impact_results);
    for (const double value :
         {last_force, last_alpha, last_approach, contact_work, peak_left})
      out.put(value);
    for (const bool flag :
         {in_contact, separated_once, peak_pending, drift_warned})
      out.put(flag);
    out.put<std::uint64_t>(length);
    // probes.csv continues from here on resume, as history.csv does.
    out.put<std::uint64_t>(probes_length);
    put_records(out, vtu_now);
    out.put(in_flight);
    put_records(out, contact_vtu ? contact_vtu->sphere_records() : Records());
    put_records(out, contact_vtu ? contact_vtu->contact_records() : Records());
  }



  void
  ImpactMonitor::load(CheckpointReader &in)
  {
    history_results([&in](auto &value) { in.get(value); }, impact_results);
    for (double *value :
         {&last_force, &last_alpha, &last_approach, &contact_work, &peak_left})
      in.get(*value);
    for (bool *flag :
         {&in_contact, &separated_once, &peak_pending, &drift_warned})
      in.get(*flag);
    std::uint64_t length = 0;
    in.get(length);
    history_length = length;
    in.get(length);
    probe_length = length;
    get_records(in, vtu_records);
    in.get(rewrite_snapshot);
    get_records(in, sphere_records);
    get_records(in, contact_records);
  }



  void
  ImpactMonitor::resume_output(const unsigned int step,
                               const double       t,
                               const TimeStepper &stepper)
  {
    // Every rank alike (each writes its piece); the flag is rank 0's on
    // one rank, and the same on every rank under MPI (written at once).
    if (vtu &&
        Utilities::MPI::max(rewrite_snapshot ? 1 : 0, plate_communicator) == 1)
      {
        fields.update(stepper, true);
        vtu->write(step,
                   t,
                   fields.displacement(),
                   fields.velocity(),
                   {},
                   &fields.acceleration());
      }
  }
} // namespace fgimpact
