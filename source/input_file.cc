#include <deal.II/base/exceptions.h>

#include <fgimpact/run_control.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

namespace fgimpact
{
  namespace
  {
    namespace fs = std::filesystem;

    constexpr std::uintmax_t max_file_size     = 16u << 20; // bytes
    constexpr unsigned int   max_include_depth = 32;

    /// The file's text, refusing what is not a regular, readable file of
    /// a sensible size.  clean is set if a byte-order mark or a carriage
    /// return was removed.
    std::string
    read_text(const std::string &filename,
              const std::string &where,
              bool              &clean)
    {
      std::error_code   error;
      const auto        status = fs::status(filename, error);
      const std::string name   = "parameter file '" + filename + "'" + where;
      AssertThrow(fs::exists(status), ExcMessage(name + " does not exist."));
      AssertThrow(!fs::is_directory(status),
                  ExcMessage(name + " is a directory, not a parameter file."));
      AssertThrow(fs::is_regular_file(status),
                  ExcMessage(name + " is not a regular file (a device, FIFO "
                                    "or socket)."));
      const auto size = fs::file_size(filename, error);
      AssertThrow(!error && size <= max_file_size,
                  ExcMessage(name + " is larger than 16 MiB."));

      std::ifstream in(filename, std::ios::binary);
      AssertThrow(in, ExcMessage(name + " cannot be opened for reading."));
      std::string text((std::istreambuf_iterator<char>(in)),
                       std::istreambuf_iterator<char>());
      AssertThrow(!in.bad(), ExcMessage(name + " cannot be read."));

      clean = false;
      if (text.compare(0, 3, "\xEF\xBB\xBF") == 0)
        {
          text.erase(0, 3);
          clean = true;
        }
      // Windows (CRLF) and old Mac (CR) line ends -> LF.
      if (text.find('\r') != std::string::npos)
        {
          std::string lf;
          lf.reserve(text.size());
          for (std::size_t i = 0; i < text.size(); ++i)
            if (text[i] != '\r')
              lf += text[i];
            else if (i + 1 == text.size() || text[i + 1] != '\n')
              lf += '\n';
          text  = lf;
          clean = true;
        }
      return text;
    }



    /// The file named by an "include" line (deal.II's syntax: comments
    /// removed, whitespace trimmed, "include name"), or "" for other lines.
    std::string
    include_target(std::string line)
    {
      const auto hash = line.find('#');
      if (hash != std::string::npos)
        line.erase(hash);
      const auto first = line.find_first_not_of(" \t");
      if (first == std::string::npos)
        return "";
      line.erase(0, first);
      if (line.compare(0, 8, "include ") != 0 &&
          line.compare(0, 8, "INCLUDE ") != 0 &&
          line.compare(0, 8, "include\t") != 0)
        return "";
      line.erase(0, 8);
      const auto begin = line.find_first_not_of(" \t");
      const auto end   = line.find_last_not_of(" \t");
      return begin == std::string::npos ? "" :
                                          line.substr(begin, end - begin + 1);
    }



    /**
     * The file's text with every include of a file that needed cleaning
     * replaced by that file's (cleaned, expanded) text; other includes stay
     * for deal.II, whose include resolves names against the working
     * directory, as here.  chain holds the files being read (canonical),
     * to find recursion.  changed is set if the text differs from the file.
     */
    std::string
    expand(const std::string     &filename,
           const std::string     &where,
           std::vector<fs::path> &chain,
           bool                  &changed)
    {
      std::error_code error;
      const fs::path  canonical = fs::weakly_canonical(filename, error);
      for (const auto &open : chain)
        AssertThrow(open != canonical,
                    ExcMessage("parameter file '" + filename + "'" + where +
                               " includes itself (recursive include)."));
      AssertThrow(chain.size() < max_include_depth,
                  ExcMessage("parameter file '" + filename + "'" + where +
                             ": includes nested deeper than 32 files."));
      chain.push_back(canonical);

      const std::string  text = read_text(filename, where, changed);
      std::istringstream lines(text);
      std::string        result, line;
      unsigned int       line_number = 0;
      while (std::getline(lines, line))
        {
          ++line_number;
          const std::string target = include_target(line);
          if (!target.empty())
            {
              bool              included_changed = false;
              const std::string included =
                expand(target,
                       " (included from line " + std::to_string(line_number) +
                         " of '" + filename + "')",
                       chain,
                       included_changed);
              if (included_changed)
                {
                  result += included;
                  if (!included.empty() && included.back() != '\n')
                    result += '\n';
                  changed = true;
                  continue;
                }
            }
          result += line;
          result += '\n';
        }
      chain.pop_back();
      return result;
    }
  } // namespace



  void
  read_parameter_file(ParameterHandler &prm, const std::string &filename)
  {
    const auto ends_with = [&](const std::string &end) {
      return filename.size() >= end.size() &&
             filename.compare(filename.size() - end.size(), end.size(), end) ==
               0;
    };
    std::error_code error;
    // XML, JSON and names that deal.II completes (PathSearch) go to
    // deal.II as they are; a .prm that exists is read here first.
    if (ends_with(".xml") || ends_with(".json") ||
        (!fs::exists(filename, error) && !fs::is_symlink(filename, error)))
      {
        prm.parse_input(filename);
        return;
      }
    std::vector<fs::path> chain;
    bool                  changed = false;
    const std::string     text    = expand(filename, "", chain, changed);
    if (!changed)
      prm.parse_input(filename);
    else
      {
        std::istringstream in(text);
        prm.parse_input(in, filename);
      }
  }
} // namespace fgimpact
