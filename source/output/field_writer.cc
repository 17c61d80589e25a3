// The VTU series of an impact run (FieldWriter): regular and interpolated
// snapshots, the peak snapshot, the ball and contact files, and their
// checkpoint section (history.csv and probes.csv: file_postprocessors.cc).

#include <fgimpact/base/exceptions.h>
#include <fgimpact/output/monitor.h>
#include <fgimpact/output/postprocessors.h>

#include <cmath>

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
  } // namespace



  FieldWriter::FieldWriter(const PlateModel         &plate,
                           const OutputParameters   &parameters,
                           const ContactModel       &contact,
                           const Point<3>           &impact_point,
                           const double              radius,
                           const ResultsAccumulator *results)
    : interval(parameters.vtu_interval)
    , snapshot_times(parameters.snapshot_times)
    , results(parameters.peak_snapshot ? results : nullptr)
    , interpolator(!snapshot_times.empty() || this->results ?
                     std::make_unique<SnapshotInterpolator>(plate) :
                     nullptr)
    , communicator(plate.get_mpi_communicator())
    , contact(contact)
    , vtu(std::make_unique<VtuWriter>(plate,
                                      parameters.directory,
                                      parameters.vtu_compression,
                                      parameters.vtu_fields))
  {
    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      contact_vtu =
        std::make_unique<ContactVtuWriter>(parameters.directory,
                                           impact_point,
                                           radius,
                                           contact,
                                           parameters.vtu_fields.mirror ?
                                             &plate.get_geometry() :
                                             nullptr);
    timer.stop();
    timer.reset();
  }



  void
  FieldWriter::start()
  {
    // A resumed run: the PVD entries of the checkpoint.
    if (resumed)
      vtu->restore(vtu_records);
    if (contact_vtu && !sphere_records.empty())
      contact_vtu->restore(sphere_records, contact_records);
  }



  void
  FieldWriter::execute(const StepRecord &record)
  {
    // A failed write of an earlier step stops the run at that step's end.
    if (!vtu || !record.fields)
      return;
    last_step = record.step;
    timer.start();
    if (interval > 0 && record.step % interval == 0)
      guarded([&]() { write_regular(record); });
    if (interpolator)
      write_extras(record);
    timer.stop();
  }



  void
  FieldWriter::guarded(const std::function<void()> &write)
  {
    try
      {
        write();
      }
    catch (const ExceptionBase &e)
      {
        keep_failure(e);
        vtu.reset();
        contact_vtu.reset();
      }
  }



  bool
  FieldWriter::all_writing() const
  {
    // Collective: a write that failed on one rank (its writer dropped)
    // must not leave the others in the next snapshot's collective calls.
    return Utilities::MPI::min(vtu ? 1u : 0u, communicator) == 1u;
  }



  void
  FieldWriter::write_regular(const StepRecord &record)
  {
    const PlateFields &f = *record.fields;
    // Collective: before the rank-0-only writer.
    const std::vector<double> node_uz = contact.contact_points().empty() ?
                                          std::vector<double>() :
                                          contact_node_uz(f.displacement());
    // The PVD time in µs, as every CSV and the log.
    const double t_us = record.t * 1e6;
    vtu->write(
      record.step, t_us, f.displacement(), f.velocity(), {}, &f.acceleration());
    if (contact_vtu)
      contact_vtu->write(Utilities::int_to_string(record.step, 5),
                         t_us,
                         record.sample->ball->w,
                         *record.sample->contact,
                         node_uz);
  }



  void
  FieldWriter::write_extras(const StepRecord &record)
  {
    interpolator->push(record);
    const bool regular = interval > 0 && record.step % interval == 0;
    // Each requested time once, at the first step that reaches it (to
    // 1 ps: a time given in us meets its step despite round-off); one on
    // this step's own time with a regular snapshot is that one.
    const double tolerance = 1e-12; // s
    for (;
         next_snapshot < snapshot_times.size() &&
         snapshot_times[next_snapshot] <= interpolator->last_time() + tolerance;
         ++next_snapshot)
      {
        const double t =
          std::min(snapshot_times[next_snapshot], interpolator->last_time());
        if (t < interpolator->first_time() - tolerance ||
            (regular && std::abs(t - record.t) <= tolerance))
          continue;
        if (!all_writing())
          return;
        // The name: the time in ns, 9 digits (solution_t000056300).
        guarded([&]() {
          write_interpolated(
            "t" + Utilities::int_to_string(
                    static_cast<unsigned int>(std::llround(t * 1e9)), 9),
            record.step,
            std::max(t, interpolator->first_time()));
        });
      }
    if (results && results->new_peak())
      write_peak(record.step);
  }



  void
  FieldWriter::write_peak(const unsigned int step)
  {
    const double t = results->peak_time();
    if (t < interpolator->first_time() || t > interpolator->last_time() ||
        !all_writing())
      return;
    guarded([&]() { write_interpolated("peak", step, t); });
    peak_written = t;
  }



  void
  FieldWriter::write_interpolated(const std::string &name,
                                  const unsigned int step,
                                  const double       t)
  {
    interpolator->interpolate(t, interpolated);
    const std::vector<double> node_uz = contact.contact_points().empty() ?
                                          std::vector<double>() :
                                          contact_node_uz(interpolated.u);
    vtu->write_extra(
      name, step, t * 1e6, interpolated.u, interpolated.v, interpolated.a);
    if (contact_vtu)
      contact_vtu->write(
        name, t * 1e6, interpolated.ball.w, interpolated.contact, node_uz);
  }



  std::vector<double>
  FieldWriter::contact_node_uz(const TrilinosWrappers::MPI::Vector &u) const
  {
    // Each DoF's value from the rank that owns it, summed over the ranks.
    const auto         &dofs = contact.contact_dofs();
    std::vector<double> local(dofs.size(), 0.), global(dofs.size(), 0.);
    for (unsigned int k = 0; k < dofs.size(); ++k)
      if (u.locally_owned_elements().is_element(dofs[k]))
        local[k] = u(dofs[k]);
    Utilities::MPI::sum(ArrayView<const double>(local),
                        communicator,
                        ArrayView<double>(global));
    return global;
  }



  bool
  FieldWriter::needs_rewrite() const
  {
    // The flag is rank 0's on one rank, and the same on every rank under
    // MPI (written at once).
    return vtu &&
           Utilities::MPI::max(rewrite_snapshot ? 1 : 0, communicator) == 1;
  }



  void
  FieldWriter::rewrite(const unsigned int step,
                       const double       t,
                       const PlateFields &fields)
  {
    vtu->write(step,
               t * 1e6,
               fields.displacement(),
               fields.velocity(),
               {},
               &fields.acceleration());
  }



  void
  FieldWriter::save(CheckpointWriter &out, const unsigned int step)
  {
    bool    in_flight = false;
    Records vtu_now;
    try
      {
        if (vtu)
          vtu_now = vtu->records(step, in_flight);
      }
    catch (const ExceptionBase &e)
      {
        keep_failure(e);
        vtu.reset();
        contact_vtu.reset();
      }
    put_records(out, vtu_now);
    out.put(in_flight);
    put_records(out, contact_vtu ? contact_vtu->sphere_records() : Records());
    put_records(out, contact_vtu ? contact_vtu->contact_records() : Records());
    out.put(next_snapshot);
    out.put(peak_written);
    if (interpolator)
      interpolator->save(out);
    // The peak fields so far (version 3); a writer lost to a failure
    // above has none.
    out.put(vtu != nullptr);
    if (vtu)
      vtu->save_peaks(out);
  }



  void
  FieldWriter::load(CheckpointReader &in)
  {
    resumed = true;
    get_records(in, vtu_records);
    in.get(rewrite_snapshot);
    get_records(in, sphere_records);
    get_records(in, contact_records);
    in.get(next_snapshot);
    in.get(peak_written);
    if (interpolator)
      interpolator->load(in);
    bool peaks = false;
    in.get(peaks);
    if (peaks && vtu)
      vtu->load_peaks(in);
  }



  void
  FieldWriter::close_output()
  {
    // A peak still rising at the last step (its time is that step's):
    // its snapshot too, not an earlier, lower one's.
    // (Every rank alike: write_peak() agrees on the writers first.)
    if (results && results->peak_time() != peak_written)
      write_peak(last_step);
    // Timed by the monitor, as every postprocessor's close_output().
    try
      {
        if (contact_vtu)
          contact_vtu->finish();
        // The peak fields are written collectively: only if no rank's
        // VTU output failed (a failed rank has dropped its writer).
        const bool all_writing =
          Utilities::MPI::min(vtu ? 1u : 0u, communicator) == 1u;
        if (vtu && all_writing)
          vtu->write_peak_fields(); // finishes the series first
        else if (vtu)
          vtu->finish();
      }
    catch (const ExceptionBase &e)
      {
        keep_failure(e);
      }
  }
} // namespace fgimpact
