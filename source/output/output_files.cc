// The plain-text outputs: CsvWriter (history.csv, probes.csv: rows handed to
// the disk whole) and SummaryWriter (summary.txt, written atomically),
// declared in output_files.h.  The VTU output is in postprocessing.cc.

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <fgimpact/base/exceptions.h>
#include <fgimpact/base/files.h>
#include <fgimpact/output/output_files.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

namespace fgimpact
{
  void
  add_pvd_entry(PvdEntries                           &entries,
                const std::pair<double, std::string> &entry)
  {
    entries.erase(std::remove_if(entries.begin(),
                                 entries.end(),
                                 [&](const auto &e) {
                                   return e.second == entry.second;
                                 }),
                  entries.end());
    entries.insert(std::upper_bound(entries.begin(),
                                    entries.end(),
                                    entry,
                                    [](const auto &a, const auto &b) {
                                      return a.first < b.first;
                                    }),
                   entry);
  }



  CsvWriter::CsvWriter(const std::string                              &filename,
                       const std::vector<std::pair<std::string, int>> &columns,
                       const std::uintmax_t resume_length)
    : filename(filename)
    , written(resume_length)
  {
    for (unsigned int i = 0; i < columns.size(); ++i)
      decimals.push_back(columns[i].second);
    if (resume_length > 0)
      {
        // Rows past the checkpoint (a run killed later) are dropped.
        check_continuable(filename, resume_length);
        std::error_code error;
        std::filesystem::resize_file(filename, resume_length, error);
        out.open(filename, std::ios::binary | std::ios::app);
        AssertThrow(out && !error,
                    ExcOutputFailure("cannot write " + filename + "."));
        return;
      }
    record_output_file(filename);
    out.open(filename, std::ios::binary);
    AssertThrow(out, ExcOutputFailure("cannot write " + filename + "."));
    for (unsigned int i = 0; i < columns.size(); ++i)
      buffer += (i ? "," : "") + columns[i].first;
    buffer += '\n';
    flush();
  }



  void
  CsvWriter::check_continuable(const std::string   &filename,
                               const std::uintmax_t resume_length)
  {
    std::error_code error;
    AssertThrow(std::filesystem::file_size(filename, error) >= resume_length &&
                  !error,
                ExcMessage(filename + " is shorter than at the checkpoint (" +
                           std::to_string(resume_length) +
                           " bytes): it cannot be continued"));
  }



  std::uintmax_t
  CsvWriter::length()
  {
    flush();
    return written;
  }



  CsvWriter::~CsvWriter()
  {
    try
      {
        flush();
      }
    catch (...)
      {}
  }



  void
  CsvWriter::write_row(const std::vector<double> &values)
  {
    Assert(values.size() == decimals.size(),
           ExcDimensionMismatch(values.size(), decimals.size()));
    char buffer_row[64];
    for (unsigned int i = 0; i < values.size(); ++i)
      {
        // Print -0.000 as 0.000: a sign flip of round-off is not a change.
        const double scale = std::pow(10., decimals[i]);
        const double v = (std::abs(values[i]) * scale < 0.5) ? 0. : values[i];
        std::snprintf(buffer_row, sizeof(buffer_row), "%.*f", decimals[i], v);
        if (i > 0)
          buffer += ',';
        buffer += buffer_row;
      }
    buffer += '\n';
    if (buffer.size() > (1u << 20) ||
        std::chrono::steady_clock::now() - last_flush > std::chrono::seconds(2))
      flush();
  }



  void
  CsvWriter::flush()
  {
    last_flush = std::chrono::steady_clock::now();
    if (buffer.empty() || !out.good())
      {
        AssertThrow(out.good(),
                    ExcOutputFailure("cannot write " + filename +
                                     " (disk full or I/O error)."));
        return;
      }
    out.write(buffer.data(), buffer.size());
    out.flush();
    written += buffer.size();
    buffer.clear();
    AssertThrow(out.good(),
                ExcOutputFailure("cannot write " + filename +
                                 " (disk full or I/O error)."));
  }



  void
  SummaryWriter::add(const std::string &name,
                     const double       value,
                     const int          decimals)
  {
    char buffer[200] = "none";
    if (std::isfinite(value))
      std::snprintf(buffer, sizeof(buffer), "%.*f", decimals, value);
    lines.emplace_back(name, buffer);
  }



  void
  SummaryWriter::add_scientific(const std::string &name, const double value)
  {
    if (!std::isfinite(value))
      return add(name, value, 0);
    char buffer[200];
    std::snprintf(buffer, sizeof(buffer), "%.6e", value);
    lines.emplace_back(name, buffer);
  }



  void
  SummaryWriter::add_text(const std::string &name, const std::string &value)
  {
    lines.emplace_back(name, value.empty() ? "none" : value);
  }



  void
  SummaryWriter::write(const std::string &filename) const
  {
    std::string text = preamble();
    for (const auto &[name, value] : lines)
      text += name + " = " + value + '\n';
    write_file_atomically(filename, text);
    // summary.json beside it: the same entries, typed, one object.
    const std::string json =
      filename.size() > 4 && filename.substr(filename.size() - 4) == ".txt" ?
        filename.substr(0, filename.size() - 4) + ".json" :
        filename + ".json";
    write_file_atomically(json, summary_json(preamble(), lines));
  }



  namespace
  {
    /// value as a JSON number (its text, a leading '+' dropped, which
    /// JSON does not allow), or "" if it is not one by JSON's grammar
    /// -?(0|[1-9]d*)(.d+)?([eE][+-]?d+)?.
    std::string
    json_number(const std::string &value)
    {
      const std::string v =
        (!value.empty() && value[0] == '+') ? value.substr(1) : value;
      std::size_t i      = (!v.empty() && v[0] == '-') ? 1 : 0;
      const auto  digits = [&v, &i]() {
        const std::size_t start = i;
        while (i < v.size() && v[i] >= '0' && v[i] <= '9')
          ++i;
        return i - start;
      };
      const std::size_t first = i;
      bool valid = digits() > 0 && !(v[first] == '0' && i - first > 1);
      if (valid && i < v.size() && v[i] == '.')
        {
          ++i;
          valid = digits() > 0;
        }
      if (valid && i < v.size() && (v[i] == 'e' || v[i] == 'E'))
        {
          ++i;
          if (i < v.size() && (v[i] == '+' || v[i] == '-'))
            ++i;
          valid = digits() > 0;
        }
      return valid && i == v.size() ? v : std::string();
    }
  } // namespace



  bool
  is_summary_number(const std::string &value)
  {
    return value == "inf" || value == "-inf" || value == "nan" ||
           value == "-nan" || !json_number(value).empty();
  }



  std::string
  summary_json(const std::string &preamble, const SummaryEntries &entries)
  {
    const auto quoted = [](const std::string &text) {
      std::string out = "\"";
      for (const char c : text)
        {
          if (c == '"' || c == '\\')
            out += '\\';
          if (static_cast<unsigned char>(c) < 0x20)
            {
              char code[8];
              std::snprintf(code, sizeof(code), "\\u%04x", c);
              out += code;
            }
          else
            out += c;
        }
      return out + '"';
    };
    // A value that is a finite number in full is a JSON number; inf, nan
    // and none (not reached, not measured) are null; the rest strings.
    const auto value_of = [&quoted](const std::string &value) {
      if (value == "none" || value == "inf" || value == "-inf" ||
          value == "nan" || value == "-nan")
        return std::string("null");
      const std::string number = json_number(value);
      return number.empty() ? quoted(value) : number;
    };
    // The provenance comments ("# key value") as one object.
    std::string text      = "{\n  \"provenance\": {";
    const char *separator = "";
    for (std::size_t start = 0; start < preamble.size();)
      {
        std::size_t end = preamble.find('\n', start);
        if (end == std::string::npos)
          end = preamble.size();
        std::string line = preamble.substr(start, end - start);
        start            = end + 1;
        if (line.rfind("# ", 0) != 0)
          continue;
        line                  = line.substr(2);
        const std::size_t gap = line.find(' ');
        text += separator;
        text += "\n    " + quoted(line.substr(0, gap)) + ": " +
                quoted(gap == std::string::npos ? "" : line.substr(gap + 1));
        separator = ",";
      }
    text += "\n  }";
    for (const auto &[name, value] : entries)
      text += ",\n  " + quoted(name) + ": " + value_of(value);
    return text + "\n}\n";
  }


  std::string &
  SummaryWriter::preamble()
  {
    static std::string lines;
    return lines;
  }



  void
  SummaryWriter::set_preamble(const std::string &comment_lines)
  {
    preamble() = comment_lines;
  }
} // namespace fgimpact



namespace fgimpact
{
  SummaryFile::SummaryFile(const std::string &directory,
                           const MPI_Comm     communicator)
    : filename(directory + "/summary.txt")
    , root(dealii::Utilities::MPI::this_mpi_process(communicator) == 0)
  {}



  void
  SummaryFile::write(const SummaryWriter &content)
  {
    keep(content);
    if (root)
      last.write(filename);
  }



  namespace
  {
    /// The value of `status` among entries ("" if none).
    std::string
    status_of(const SummaryEntries &entries)
    {
      for (const auto &[name, value] : entries)
        if (name == "status")
          return value;
      return "";
    }
  } // namespace



  void
  SummaryFile::write_failed(const SummaryWriter &content)
  {
    const std::string wanted = status_of(content.entries());
    if (!wanted.empty() && status() == wanted)
      return;
    try
      {
        write(content);
      }
    catch (...)
      {}
  }



  std::string
  SummaryFile::status() const
  {
    return status_of(last.entries());
  }



  std::string
  study_csv(const std::vector<std::string>              &paths,
            const std::vector<std::vector<std::string>> &values,
            const std::vector<SummaryEntries>           &summaries)
  {
    std::vector<std::string> keys;
    for (const auto &entries : summaries)
      for (const auto &[key, value] : entries)
        if (std::find(keys.begin(), keys.end(), key) == keys.end())
          keys.push_back(key);
    std::ostringstream csv;
    csv << "case";
    for (const auto &path : paths)
      csv << ',' << path;
    for (const auto &key : keys)
      csv << ',' << key;
    csv << '\n';
    std::vector<std::map<std::string, std::string>> rows(summaries.size());
    std::set<std::string>                           words;
    for (unsigned int i = 0; i < summaries.size(); ++i)
      for (const auto &[key, value] : summaries[i])
        {
          rows[i][key] = value;
          if (value != "none" && !is_summary_number(value))
            words.insert(key);
        }
    for (unsigned int i = 0; i < summaries.size(); ++i)
      {
        csv << i;
        for (const auto &value : values[i])
          csv << ',' << value;
        for (const auto &key : keys)
          {
            const auto value = rows[i].find(key);
            const bool known =
              value != rows[i].end() && value->second != "none";
            csv << ','
                << (known                 ? value->second :
                    words.count(key) != 0 ? "none" :
                                            "");
          }
        csv << '\n';
      }
    return csv.str();
  }
} // namespace fgimpact
