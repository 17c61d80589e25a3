#include <deal.II/base/exceptions.h>

#include <fgimpact/base/exceptions.h>
#include <fgimpact/base/files.h>

#include <cstdio>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <istream>
#include <iterator>
#include <mutex>
#include <set>
#include <unistd.h>

namespace fgimpact
{

  void
  write_file_atomically(const std::string &filename, const std::string &text)
  {
    record_output_file(filename);
    const std::string temporary = filename + ".tmp";
    bool              ok        = false;
    {
      std::ofstream out(temporary, std::ios::binary);
      out.write(text.data(), text.size());
      out.flush();
      out.close();
      ok = !out.fail();
    }
    ok = ok && std::rename(temporary.c_str(), filename.c_str()) == 0;
    if (!ok)
      {
        std::remove(temporary.c_str());
        AssertThrow(false,
                    ExcOutputFailure("cannot write " + filename +
                                     " (disk full or I/O error)."));
      }
  }



  namespace
  {
    /// The files this process has recorded (record_output_file()).
    std::mutex &
    manifest_mutex()
    {
      static std::mutex mutex;
      return mutex;
    }

    std::set<std::string> &
    recorded_files()
    {
      static std::set<std::string> files;
      return files;
    }

    /// The directories whose manifest recorded_files() holds: a resumed
    /// run appends only what its killed predecessor did not list.
    std::set<std::string> &
    loaded_manifests()
    {
      static std::set<std::string> directories;
      return directories;
    }
  } // namespace



  void
  record_output_file(const std::string &path)
  {
    namespace fs        = std::filesystem;
    const fs::path file = fs::absolute(path).lexically_normal();
    const std::lock_guard<std::mutex> guard(manifest_mutex());
    if (loaded_manifests().insert(file.parent_path().string()).second)
      for (const auto &name : read_manifest(file.parent_path().string()))
        recorded_files().insert((file.parent_path() / name).string());
    if (!recorded_files().insert(file.string()).second)
      return;
    const std::string manifest =
      (file.parent_path() / manifest_file_name).string();
    const std::string line = file.filename().string() + "\n";
    const int         fd =
      ::open(manifest.c_str(),
             O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC | O_NOFOLLOW,
             0644);
    const bool written = fd >= 0 && ::write(fd, line.data(), line.size()) ==
                                      static_cast<ssize_t>(line.size());
    if (fd >= 0)
      ::close(fd);
    if (!written)
      {
        recorded_files().erase(file.string());
        AssertThrow(false,
                    ExcOutputFailure("cannot write " + manifest +
                                     " (disk full or I/O error)."));
      }
  }



  std::set<std::string>
  read_manifest(const std::string &directory)
  {
    std::set<std::string> names;
    std::ifstream         in(directory + "/" + manifest_file_name);
    for (std::string line; std::getline(in, line);)
      if (!line.empty())
        names.insert(line);
    return names;
  }



  void
  reset_manifest(const std::string &directory)
  {
    namespace fs        = std::filesystem;
    const fs::path path = fs::absolute(directory).lexically_normal();
    const std::lock_guard<std::mutex> guard(manifest_mutex());
    auto                             &files = recorded_files();
    for (auto it = files.begin(); it != files.end();)
      it =
        fs::path(*it).parent_path() == path ? files.erase(it) : std::next(it);
    loaded_manifests().insert(path.string()); // empty from now on
    std::error_code error;
    fs::remove(path / manifest_file_name, error);
  }



  namespace
  {
    namespace fs = std::filesystem;
    /// The largest input file this program reads (a .prm, a profile).
    constexpr std::uintmax_t max_file_size = 16u << 20; // bytes
  }                                                     // namespace



  /// All of in, but refusing more than max_file_size bytes (standard
  /// input may be endless: /dev/zero).
  std::string
  read_text(std::istream &in, const std::string &what)
  {
    std::string text;
    char        buffer[1 << 16];
    while (in.read(buffer, sizeof(buffer)) || in.gcount() > 0)
      {
        text.append(buffer, in.gcount());
        AssertThrow(text.size() <= max_file_size,
                    ExcMessage(what + " is larger than 16 MiB."));
      }
    AssertThrow(!in.bad(), ExcMessage(what + " cannot be read."));
    return text;
  }



  std::string
  read_named_file(const std::string &filename,
                  const std::string &what,
                  const std::string &kind)
  {
    std::error_code error;
    const auto      status = fs::status(filename, error);
    AssertThrow(fs::exists(status), ExcMessage(what + " does not exist."));
    AssertThrow(!fs::is_directory(status),
                ExcMessage(what + " is a directory, not " + kind + "."));
    AssertThrow(fs::is_regular_file(status),
                ExcMessage(what + " is not a regular file (a device, FIFO "
                                  "or socket)."));
    AssertThrow(fs::file_size(filename, error) <= max_file_size && !error,
                ExcMessage(what + " is larger than 16 MiB."));
    std::ifstream in(filename, std::ios::binary);
    AssertThrow(in, ExcMessage(what + " cannot be opened for reading."));
    return read_text(in, what);
  }
} // namespace fgimpact
