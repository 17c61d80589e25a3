// The postprocessors that write CSV files: history.csv and probes.csv (the
// VTU/PVD series: field_writer.cc).  Each keeps a failed write in
// output_failure() and drops only its own writer.

#include <fgimpact/base/exceptions.h>
#include <fgimpact/output/monitor.h>
#include <fgimpact/output/postprocessors.h>

#include <cmath>

namespace fgimpact
{
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
} // namespace fgimpact
