// The postprocessors that write files: history.csv, probes.csv and the
// VTU/PVD series.  Each keeps a failed write in output_failure() and drops
// only its own writer.

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



  void
  Postprocessor::keep_failure(const ExceptionBase &e)
  {
    output_failure_message = message_of(e);
  }



  namespace
  {
    std::vector<std::pair<std::string, int>>
    header_of(const std::vector<HistoryColumn> &columns)
    {
      std::vector<std::pair<std::string, int>> header;
      for (const auto &column : columns)
        header.emplace_back(column.name, column.decimals);
      return header;
    }
  } // namespace



  CsvPostprocessor::CsvPostprocessor(
    const std::string                              &filename,
    const std::vector<std::pair<std::string, int>> &columns,
    const bool                                      root)
    : filename(filename)
    , columns(columns)
    , root(root)
  {}



  void
  CsvPostprocessor::start()
  {
    if (!root)
      return;
    try
      {
        csv = std::make_unique<CsvWriter>(filename, columns, resume_length);
      }
    catch (const ExceptionBase &e)
      {
        keep_failure(e);
      }
  }



  void
  CsvPostprocessor::write_row(const std::vector<double> &row)
  {
    try
      {
        if (csv)
          csv->write_row(row);
      }
    catch (const ExceptionBase &e)
      {
        keep_failure(e);
        csv.reset();
      }
  }



  void
  CsvPostprocessor::save(CheckpointWriter &out, const unsigned int)
  {
    std::uintmax_t length = 0;
    try
      {
        if (csv)
          length = csv->length();
      }
    catch (const ExceptionBase &e)
      {
        keep_failure(e);
        csv.reset();
      }
    out.put<std::uint64_t>(length);
  }



  void
  CsvPostprocessor::load(CheckpointReader &in)
  {
    std::uint64_t length = 0;
    in.get(length);
    resume_length = length;
    // Checked here, before start() truncates any file to its checkpoint
    // length: a resume that cannot continue every file touches none.
    if (!root || length == 0)
      return;
    try
      {
        CsvWriter::check_continuable(filename, length);
      }
    catch (const ExceptionBase &e)
      {
        keep_failure(e);
      }
  }



  void
  CsvPostprocessor::close_output()
  {
    try
      {
        if (csv)
          csv->flush();
      }
    catch (const ExceptionBase &e)
      {
        keep_failure(e);
      }
  }



  HistoryWriter::HistoryWriter(const std::string                &directory,
                               const std::vector<HistoryColumn> &columns,
                               const bool                        root)
    : CsvPostprocessor(directory + "/history.csv", header_of(columns), root)
    , columns(columns)
  {}



  void
  HistoryWriter::add_observer(const RowObserver &observer)
  {
    observers.push_back(observer);
  }



  void
  HistoryWriter::execute(const StepRecord &record)
  {
    // A member: no allocation per step.
    row.resize(columns.size());
    for (unsigned int i = 0; i < columns.size(); ++i)
      row[i] = columns[i].value(*record.sample);
    write_row(row);
    for (const auto &observer : observers)
      observer(row);
  }



  ProbeWriter::ProbeWriter(std::unique_ptr<const ProbeSet>        probe_set,
                           std::vector<ImpactResults::ProbePeak> &peaks,
                           const std::string                     &directory,
                           const double                           whole,
                           const bool                             root)
    : CsvPostprocessor(directory + "/probes.csv", probe_set->columns(), root)
    , probes(std::move(probe_set))
    , peaks(peaks)
    , whole(whole)
  {
    peaks.clear();
    for (std::size_t i = 0; i < probes->locations().size(); ++i)
      {
        const Point<3> &x = probes->locations()[i];
        peaks.push_back({probes->get_names()[i], {{x[0], x[1], x[2]}}, 0., 0.});
      }
  }



  void
  ProbeWriter::execute(const StepRecord &record)
  {
    // The convolution engine of a study has no fields (probes.csv comes
    // from --study-case K).  Every rank evaluates: it is collective.
    if (!record.fields)
      return;
    const PlateFields &f      = *record.fields;
    ProbeValues        values = probes->evaluate(f.displacement(),
                                          f.velocity(),
                                          f.acceleration(),
                                          f.lumped_mass());
    values.support_reaction_z *= whole; // a part's supports: scaled up
    write_row(probes->row(record.t, values));
    for (std::size_t i = 0; i < peaks.size(); ++i)
      {
        // sqrt(3/2 s:s) of the deviator s (the norm counts xy twice).
        const double von_mises =
          std::sqrt(1.5) * deviator(values.stress[i]).norm();
        if (von_mises > peaks[i].von_mises)
          {
            peaks[i].von_mises = von_mises;
            peaks[i].time      = record.t;
          }
      }
  }



  void
  ProbeWriter::save(CheckpointWriter &out, const unsigned int step)
  {
    CsvPostprocessor::save(out, step);
    for (const auto &peak : peaks)
      {
        out.put<double>(peak.von_mises);
        out.put<double>(peak.time);
      }
  }



  void
  ProbeWriter::load(CheckpointReader &in)
  {
    CsvPostprocessor::load(in);
    for (auto &peak : peaks)
      {
        in.get(peak.von_mises);
        in.get(peak.time);
      }
  }



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
