#include <deal.II/base/utilities.h>

#include <fgimpact/base/checkpoint.h>
#include <fgimpact/base/exceptions.h>
#include <fgimpact/base/files.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace fgimpact
{
  namespace fs = std::filesystem;

  namespace
  {
    const char magic[8] = {'F', 'G', 'I', 'M', 'P', 'C', 'K', 'P'};
    // 2: probes.csv's length in the monitor's part; the header hashed.
    // 3: the contact set's size before the stepper's state.
    // 4: named, versioned sections (CheckpointWriter::section()).
    const unsigned int format_version = 4;

    /// FNV-1a, 64 bit: detects a torn or damaged file, and tells
    /// parameter texts apart.
    std::uint64_t
    hash_of(const std::string &data)
    {
      std::uint64_t h = 14695981039346656037ull;
      for (const char c : data)
        {
          h ^= static_cast<unsigned char>(c);
          h *= 1099511628211ull;
        }
      return h;
    }

    std::string
    rank_file(const std::string &directory, const unsigned int rank)
    {
      return directory + "/rank_" + Utilities::int_to_string(rank, 4) + ".bin";
    }

    /// checkpoint/, or checkpoint.old/ if a run died while replacing it.
    std::string
    existing_checkpoint(const std::string &directory)
    {
      for (const std::string name : {"/checkpoint", "/checkpoint.old"})
        if (fs::is_directory(directory + name))
          return directory + name;
      return "";
    }

    struct Header
    {
      unsigned int n_ranks = 0, rank = 0, step = 0;
      std::string  parameters;
      std::string  payload;
    };

    /// Read and check one rank's file; throws ExcMessage naming it.
    Header
    read_file(const std::string &filename)
    {
      std::ifstream in(filename, std::ios::binary);
      AssertThrow(in, ExcMessage("cannot read the checkpoint " + filename));
      std::stringstream whole;
      whole << in.rdbuf();
      CheckpointReader  reader(whole.str());
      const std::string damaged =
        "the checkpoint " + filename + " is damaged or not a checkpoint";
      Header header;
      try
        {
          char name[8];
          reader.get(name);
          AssertThrow(std::equal(name, name + 8, magic), ExcMessage(damaged));
          unsigned int  version         = 0;
          std::uint64_t parameters_hash = 0, payload_hash = 0;
          reader.get(version);
          AssertThrow(version == format_version,
                      ExcMessage("the checkpoint " + filename +
                                 " has format version " +
                                 std::to_string(version) + ", this program " +
                                 std::to_string(format_version)));
          // The whole file (header included: ranks, rank, step) is
          // hashed, so that a damaged byte anywhere says so instead of
          // being read as a different step or rank count.
          const std::string &data      = whole.str();
          std::uint64_t      file_hash = 0;
          AssertThrow(data.size() >= sizeof(file_hash), ExcMessage(damaged));
          std::memcpy(&file_hash,
                      data.data() + data.size() - sizeof(file_hash),
                      sizeof(file_hash));
          AssertThrow(file_hash ==
                        hash_of(
                          data.substr(0, data.size() - sizeof(file_hash))),
                      ExcMessage(damaged));
          reader.get(header.n_ranks);
          reader.get(header.rank);
          reader.get(header.step);
          reader.get(parameters_hash);
          reader.get(header.parameters);
          reader.get(header.payload);
          reader.get(payload_hash);
          AssertThrow(parameters_hash == hash_of(header.parameters) &&
                        payload_hash == hash_of(header.payload),
                      ExcMessage(damaged));
        }
      catch (const ExcMessage &)
        {
          throw;
        }
      catch (...)
        {
          AssertThrow(false, ExcMessage(damaged));
        }
      return header;
    }

    /// "Section/Entry" -> value of a PRM text printed with Short.
    std::map<std::string, std::string>
    entries_of(const std::string &text)
    {
      std::map<std::string, std::string> entries;
      std::vector<std::string>           path;
      std::istringstream                 in(text);
      std::string                        line;
      while (std::getline(in, line))
        {
          line = Utilities::trim(line);
          if (line.rfind("subsection ", 0) == 0)
            path.push_back(Utilities::trim(line.substr(11)));
          else if (line == "end" && !path.empty())
            path.pop_back();
          else if (line.rfind("set ", 0) == 0 &&
                   line.find('=') != std::string::npos)
            {
              const auto  eq   = line.find('=');
              std::string name = Utilities::trim(line.substr(4, eq - 4));
              for (auto p = path.rbegin(); p != path.rend(); ++p)
                name = *p + "/" + name;
              entries[name] = Utilities::trim(line.substr(eq + 1));
            }
        }
      return entries;
    }
  } // namespace



  void
  CheckpointWriter::put(const std::string &text)
  {
    put<std::uint64_t>(text.size());
    buffer += text;
  }



  void
  CheckpointWriter::put(const std::vector<double> &values)
  {
    put<std::uint64_t>(values.size());
    buffer.append(reinterpret_cast<const char *>(values.data()),
                  values.size() * sizeof(double));
  }



  void
  CheckpointWriter::put(const std::vector<bool> &values)
  {
    put<std::uint64_t>(values.size());
    for (const bool value : values)
      put<char>(value ? 1 : 0);
  }



  void
  CheckpointWriter::put(const TrilinosWrappers::MPI::Vector &vector)
  {
    put<std::uint64_t>(vector.size());
    put(std::vector<double>(vector.begin(), vector.end()));
  }



  CheckpointReader::CheckpointReader(std::string data)
    : buffer(std::move(data))
  {}



  const char *
  CheckpointReader::take(const std::size_t n)
  {
    AssertThrow(position + n <= buffer.size(),
                ExcMessage("the checkpoint ends early (damaged, or written "
                           "by a different version of the program)"));
    const char *p = buffer.data() + position;
    position += n;
    return p;
  }



  CheckpointReader
  CheckpointReader::section(const std::string  &name,
                            const std::uint32_t version) const
  {
    // Scan the section headers in place (the payload holds the vectors:
    // no copy of it), then copy the one section asked for.
    std::size_t at   = 0;
    const auto  skip = [&](void *to, const std::size_t n) {
      AssertThrow(at + n <= buffer.size(),
                  ExcMessage("the checkpoint ends early (damaged, or written "
                              "by a different version of the program)"));
      if (to != nullptr)
        std::memcpy(to, buffer.data() + at, n);
      at += n;
    };
    while (at < buffer.size())
      {
        std::uint64_t name_length = 0, length = 0;
        std::uint32_t found_version = 0;
        skip(&name_length, sizeof(name_length));
        const std::size_t name_at = at;
        skip(nullptr, name_length);
        skip(&found_version, sizeof(found_version));
        skip(&length, sizeof(length));
        const std::size_t data_at = at;
        skip(nullptr, length);
        if (buffer.compare(name_at, name_length, name) != 0)
          continue;
        AssertThrow(
          found_version == version,
          ExcMessage("the checkpoint's section '" + name + "' has version " +
                     std::to_string(found_version) +
                     ", this program reads version " + std::to_string(version) +
                     " (written by a different version of the "
                     "program: run again without --resume)"));
        CheckpointReader part(buffer.substr(data_at, length));
        part.step = step;
        return part;
      }
    AssertThrow(false,
                ExcMessage("the checkpoint has no section '" + name +
                           "' (written by a different version of the "
                           "program: run again without --resume)"));
    return CheckpointReader("");
  }



  void
  CheckpointReader::get(std::string &text)
  {
    std::uint64_t n = 0;
    get(n);
    text.assign(take(n), n);
  }



  void
  CheckpointReader::get(std::vector<double> &values)
  {
    std::uint64_t n = 0;
    get(n);
    values.resize(n);
    if (n > 0)
      std::memcpy(values.data(), take(n * sizeof(double)), n * sizeof(double));
  }



  void
  CheckpointReader::get(std::vector<bool> &values)
  {
    std::uint64_t n = 0;
    get(n);
    values.resize(n);
    for (std::uint64_t i = 0; i < n; ++i)
      {
        char c = 0;
        get(c);
        values[i] = (c != 0);
      }
  }



  void
  CheckpointReader::get(TrilinosWrappers::MPI::Vector &vector)
  {
    std::uint64_t       global_size = 0;
    std::vector<double> values;
    get(global_size);
    get(values);
    AssertThrow(global_size == vector.size() &&
                  values.size() == vector.locally_owned_size(),
                ExcMessage("the checkpoint's vectors do not match this mesh "
                           "and partition"));
    std::copy(values.begin(), values.end(), vector.begin());
  }



  void
  write_checkpoint(const std::string &directory,
                   const MPI_Comm     comm,
                   const unsigned int step,
                   const std::string &parameters_text,
                   const std::string &payload)
  {
    const unsigned int rank    = Utilities::MPI::this_mpi_process(comm);
    const std::string  fresh   = directory + "/checkpoint.new";
    const std::string  current = directory + "/checkpoint";
    const std::string  old     = directory + "/checkpoint.old";
    std::error_code    error;
    if (rank == 0)
      {
        fs::remove_all(fresh, error);
        fs::create_directory(fresh, error);
      }
    Utilities::MPI::broadcast(comm, 0, 0); // the directory exists

    CheckpointWriter file;
    file.put(magic);
    file.put(format_version);
    file.put(Utilities::MPI::n_mpi_processes(comm));
    file.put(rank);
    file.put(step);
    file.put(hash_of(parameters_text));
    file.put(parameters_text);
    file.put(payload);
    file.put(hash_of(payload));
    file.put(hash_of(file.data()));
    std::string failure;
    try
      {
        write_file_atomically(rank_file(fresh, rank), file.data());
      }
    catch (const ExcOutputFailure &e)
      {
        failure = one_line(message_of(e));
      }
    // Complete on every rank, or the last good checkpoint stays.
    for (const auto &message : Utilities::MPI::all_gather(comm, failure))
      AssertThrow(message.empty(), ExcOutputFailure(message));
    std::string rename_failure;
    if (rank == 0)
      {
        fs::remove_all(old, error);
        if (fs::exists(current))
          fs::rename(current, old, error);
        if (!error)
          fs::rename(fresh, current, error);
        if (error)
          rename_failure = "cannot rename " + fresh + " to " + current + ": " +
                           error.message();
        else
          fs::remove_all(old, error);
      }
    rename_failure = Utilities::MPI::broadcast(comm, rename_failure, 0);
    AssertThrow(rename_failure.empty(), ExcOutputFailure(rename_failure));
  }



  CheckpointReader
  read_checkpoint(const std::string &directory, const MPI_Comm comm)
  {
    const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
    std::string        where, failure;
    Header             header;
    if (rank == 0)
      where = existing_checkpoint(directory);
    where = Utilities::MPI::broadcast(comm, where, 0);
    AssertThrow(!where.empty(),
                ExcMessage("no checkpoint in " + directory + " to resume"));
    try
      {
        header = read_file(rank_file(where, rank));
        AssertThrow(header.rank == rank &&
                      header.n_ranks == Utilities::MPI::n_mpi_processes(comm),
                    ExcMessage("the checkpoint in " + where +
                               " was written by a different number of MPI "
                               "ranks"));
      }
    catch (const ExceptionBase &e)
      {
        failure = one_line(message_of(e));
      }
    for (const auto &message : Utilities::MPI::all_gather(comm, failure))
      AssertThrow(message.empty(), ExcMessage(message));
    AssertThrow(Utilities::MPI::min(header.step, comm) ==
                  Utilities::MPI::max(header.step, comm),
                ExcMessage("the checkpoint files in " + where +
                           " belong to different time steps"));
    CheckpointReader reader(std::move(header.payload));
    reader.step = header.step;
    return reader;
  }



  unsigned int
  check_resume(const std::string &directory,
               const std::string &parameters_text,
               const unsigned int n_ranks)
  {
    const std::string where = existing_checkpoint(directory);
    AssertThrow(!where.empty(),
                ExcMessage("--resume " + directory +
                           ": no checkpoint there (Output/Checkpoint interval "
                           "= 0, or the run stopped before its first one)"));
    const Header header = read_file(rank_file(where, 0));
    AssertThrow(header.n_ranks == n_ranks,
                ExcMessage("--resume " + directory +
                           ": the checkpoint was "
                           "written by " +
                           std::to_string(header.n_ranks) +
                           " MPI ranks; resume on the same number (now " +
                           std::to_string(n_ranks) + ")"));
    // Entries that do not change the computed history.
    const std::vector<std::string> free_entries = {
      "Output/Directory",
      "Output/Log interval",
      "Output/Print timing",
      "Output/Overwrite",
      "Output/Checkpoint interval",
      "Time integration/End time",
      "Time integration/Maximum end time"};
    auto        stored = entries_of(header.parameters);
    auto        now    = entries_of(parameters_text);
    std::string changed;
    for (auto &entry : now)
      if (stored[entry.first] != entry.second &&
          std::find(free_entries.begin(), free_entries.end(), entry.first) ==
            free_entries.end())
        changed += (changed.empty() ? "" : ", ") + entry.first + " (" +
                   stored[entry.first] + " -> " + entry.second + ")";
    AssertThrow(changed.empty(),
                ExcMessage("--resume " + directory +
                           ": parameters changed since the checkpoint would "
                           "change the results: " +
                           changed + "; run anew instead"));
    return header.step;
  }



  bool
  is_checkpoint_directory(const std::string &name)
  {
    return name == "checkpoint" || name == "checkpoint.new" ||
           name == "checkpoint.old";
  }
} // namespace fgimpact
