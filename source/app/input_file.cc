#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <fgimpact/app/input_file.h>
#include <fgimpact/app/prm_names.h>
#include <fgimpact/base/exceptions.h>
#include <fgimpact/base/files.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <map>
#include <regex>
#include <sstream>

namespace fgimpact
{
  namespace
  {
    namespace fs = std::filesystem;

    /// The deepest chain of include lines taken.
    constexpr unsigned int max_include_depth = 32;

    bool
    ends_with(const std::string &s, const std::string &end)
    {
      return s.size() >= end.size() &&
             s.compare(s.size() - end.size(), end.size(), end) == 0;
    }

    /// The text of a parameter file as given, refusing what is not a
    /// regular, readable file of a sensible size.  what names the file
    /// (and the line that includes it).
    std::string
    read_regular_file(const fs::path &filename, const std::string &what)
    {
      return read_named_file(filename.string(), what, "a parameter file");
    }

    /// Without a UTF-8 byte-order mark, Windows (CRLF) and old Mac (CR)
    /// line ends made LF: the line numbers stay those of the file.  A NUL
    /// byte is refused (`what` names the file): deal.II would cut the
    /// value there and run with the rest ("Directory = a\0b" into "a").
    std::string
    clean_text(const std::string &text, const std::string &what)
    {
      if (const auto nul = text.find('\0'); nul != std::string::npos)
        AssertThrow(false,
                    ExcMessage(what + " line " +
                               std::to_string(1 + std::count(text.begin(),
                                                             text.begin() + nul,
                                                             '\n')) +
                               " contains a NUL byte: a parameter file is "
                               "text (a value would be cut there)."));
      const std::size_t start = text.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;
      std::string       clean;
      clean.reserve(text.size());
      for (std::size_t i = start; i < text.size(); ++i)
        if (text[i] != '\r')
          clean += text[i];
        else if (i + 1 == text.size() || text[i + 1] != '\n')
          clean += '\n';
      return clean;
    }

    std::string
    quoted_section(const std::string &path)
    {
      return path.empty() ? "at the top level" : "in subsection '" + path + "'";
    }
  } // namespace



  InputFile::InputFile(const std::string &filename)
    : name(filename == "-" ? std::string("standard input") : filename)
    , xml_or_json(ends_with(filename, ".xml") || ends_with(filename, ".json"))
  {
    const std::string what = filename == "-" ?
                               std::string("standard input") :
                               "parameter file '" + filename + "'";
    original_text          = filename == "-" ? read_text(std::cin, what) :
                                               read_regular_file(filename, what);
    if (xml_or_json)
      expanded_text = clean_text(original_text, what);
    else
      {
        std::vector<std::string> chain;
        expand(name, clean_text(original_text, what), chain);
      }
  }



  InputFile::InputFile(const std::string &name, const std::string &text)
    : name(name == "-" ? std::string("standard input") : name)
    , xml_or_json(ends_with(name, ".xml") || ends_with(name, ".json"))
    , original_text(text)
    , expanded_text(text)
  {}



  const std::string &
  InputFile::input_name() const
  {
    return name;
  }



  const std::string &
  InputFile::original() const
  {
    return original_text;
  }



  const std::string &
  InputFile::expanded() const
  {
    return expanded_text;
  }



  void
  InputFile::expand(const std::string        &filename,
                    const std::string        &text,
                    std::vector<std::string> &chain)
  {
    // Includes of standard input are relative to the working directory.
    const bool     is_stdin = (filename == "standard input");
    const fs::path directory =
      is_stdin ? fs::path() : fs::path(filename).parent_path();
    std::error_code error;
    chain.push_back(is_stdin ? filename :
                               fs::weakly_canonical(filename, error).string());
    std::istringstream in(text);
    unsigned int       line_number = 0;
    for (std::string line; std::getline(in, line);)
      {
        ++line_number;
        const std::string content = prm_names::strip_comment(line);
        if (!prm_names::starts_with_keyword(content, "include"))
          {
            expanded_text += line + "\n";
            origins.push_back({filename, line_number});
            continue;
          }
        const std::string where =
          filename + " line " + std::to_string(line_number) + ": ";
        const fs::path included(Utilities::trim(content.substr(7)));
        fs::path       resolved = included;
        if (included.is_relative() && fs::exists(directory / included, error))
          resolved = directory / included;
        AssertThrow(fs::exists(resolved, error),
                    ExcMessage(where + "the included file '" +
                               included.string() +
                               "' does not exist (looked in '" +
                               (directory.empty() ? std::string(".") :
                                                    directory.string()) +
                               "' and the working directory)."));
        const std::string canonical =
          fs::weakly_canonical(resolved, error).string();
        for (const std::string &open : chain)
          AssertThrow(open != canonical,
                      ExcMessage(where + "'" + included.string() +
                                 "' is already being read: the file includes "
                                 "itself (recursive include)."));
        AssertThrow(chain.size() < max_include_depth,
                    ExcMessage(where + "includes nested deeper than " +
                               std::to_string(max_include_depth) + " files."));
        const std::string included_what =
          where + "the included file '" + included.string() + "'";
        const std::string included_text =
          read_regular_file(resolved, included_what);
        expand(resolved.string(),
               clean_text(included_text, included_what),
               chain);
      }
    chain.pop_back();
  }



  void
  InputFile::parse_into(ParameterHandler               &prm,
                        const std::vector<std::string> &overrides) const
  {
    try
      {
        std::istringstream in(expanded_text);
        if (ends_with(name, ".xml"))
          prm.parse_input_from_xml(in);
        else if (ends_with(name, ".json"))
          prm.parse_input_from_json(in);
        else
          prm.parse_input(in, name);
      }
    catch (const ExceptionBase &e)
      {
        const std::string undeclared =
          xml_or_json ? std::string() : find_undeclared_name(prm);
        if (!undeclared.empty())
          throw ExcMessage(undeclared);
        // deal.II counts lines of the expanded text: name the true origin.
        std::string      message = message_of(e);
        std::smatch      match;
        const std::regex line_of_file("Line <([0-9]+)> of file <[^>]*>:?");
        if (std::regex_search(message, match, line_of_file))
          {
            const unsigned int n = std::stoul(match[1].str());
            if (n >= 1 && n <= origins.size())
              {
                const Origin &o = origins[n - 1];
                message         = match.prefix().str() + "line " +
                          std::to_string(o.line) +
                          (o.file == name ? "" : " of " + o.file) + ":" +
                          match.suffix().str();
              }
          }
        throw ExcMessage(message);
      }
    for (const std::string &assignment : overrides)
      apply_override(prm, assignment);
  }



  std::string
  InputFile::find_undeclared_name(const ParameterHandler &prm) const
  {
    const prm_names::DeclaredNames names = prm_names::declared_names(prm);
    std::vector<std::string>       path;
    std::istringstream             in(expanded_text);
    unsigned int                   index = 0;
    for (std::string line; std::getline(in, line); ++index)
      {
        const std::string content = prm_names::strip_comment(line);
        const std::string where =
          index < origins.size() ?
            "line " + std::to_string(origins[index].line) +
              (origins[index].file == name ? "" :
                                             " of " + origins[index].file) +
              ": " :
            "";
        const std::string here = prm_names::join(path, "/");
        if (prm_names::starts_with_keyword(content, "subsection"))
          {
            const std::string section = Utilities::trim(content.substr(10));
            path.push_back(section);
            const std::string full = prm_names::join(path, "/");
            if (std::find(names.subsections.begin(),
                          names.subsections.end(),
                          full) == names.subsections.end())
              {
                std::vector<std::string> siblings;
                for (const std::string &s : names.subsections)
                  if (s.rfind(here.empty() ? "" : here + "/", 0) == 0 &&
                      s.find('/', here.empty() ? 0 : here.size() + 1) ==
                        std::string::npos)
                    siblings.push_back(
                      here.empty() ? s : s.substr(here.size() + 1));
                return where + "no subsection '" + section + "' " +
                       quoted_section(here) +
                       prm_names::did_you_mean(
                         prm_names::closest(section, siblings));
              }
          }
        else if (content == "end" || content == "END")
          {
            if (!path.empty())
              path.pop_back();
          }
        else if (prm_names::starts_with_keyword(content, "set"))
          {
            const std::string entry =
              Utilities::trim(content.substr(3, content.find('=') - 3));
            const std::string full = here.empty() ? entry : here + "/" + entry;
            if (names.entries.count(full) == 0)
              return where + "no entry '" + entry + "' " +
                     quoted_section(here) +
                     prm_names::did_you_mean(
                       prm_names::suggest_entry(names, here, entry));
          }
      }
    return "";
  }



  void
  apply_override(ParameterHandler  &prm,
                 const std::string &assignment,
                 const std::string &option)
  {
    const std::string what = option + " '" + assignment + "': ";
    const auto        eq   = assignment.find('=');
    AssertThrow(eq != std::string::npos,
                ExcMessage(what + "expected \"Section/Entry=value\""));
    const std::string path  = Utilities::trim(assignment.substr(0, eq));
    const std::string value = Utilities::trim(assignment.substr(eq + 1));

    const prm_names::DeclaredNames names = prm_names::declared_names(prm);
    const auto                     entry = names.entries.find(path);
    if (entry == names.entries.end())
      {
        std::vector<std::string> all;
        for (const auto &e : names.entries)
          all.push_back(e.first);
        std::string suggestion = prm_names::closest(path, all);
        if (suggestion.empty())
          {
            const auto slash = path.rfind('/');
            suggestion       = prm_names::suggest_entry(names,
                                                  "",
                                                  slash == std::string::npos ?
                                                          path :
                                                          path.substr(slash + 1));
          }
        throw ExcMessage(what + "no entry '" + path + "' is declared" +
                         prm_names::did_you_mean(suggestion));
      }
    const std::vector<std::string> &components = entry->second;
    for (std::size_t i = 0; i + 1 < components.size(); ++i)
      prm.enter_subsection(components[i]);
    std::string error;
    try
      {
        prm.set(components.back(), value);
      }
    catch (const ExceptionBase &e)
      {
        error = message_of(e);
      }
    for (std::size_t i = 0; i + 1 < components.size(); ++i)
      prm.leave_subsection();
    AssertThrow(error.empty(),
                ExcMessage(what + "the value '" + value +
                           "' is not allowed for " + path + ": " + error));
  }
} // namespace fgimpact
