// The names a ParameterHandler declares and the nearest to a misspelt one
// (prm_names.h).

#include <deal.II/base/utilities.h>

#include <fgimpact/app/prm_names.h>

#include <algorithm>
#include <cctype>
#include <sstream>

namespace fgimpact
{
  namespace
  {
    std::string
    lower(std::string s)
    {
      for (char &c : s)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      return s;
    }

    /// Edit distance (insert, delete, substitute), ignoring case.
    unsigned int
    edit_distance(const std::string &a_in, const std::string &b_in)
    {
      const std::string         a = lower(a_in), b = lower(b_in);
      std::vector<unsigned int> row(b.size() + 1);
      for (unsigned int j = 0; j <= b.size(); ++j)
        row[j] = j;
      for (unsigned int i = 1; i <= a.size(); ++i)
        {
          unsigned int diagonal = row[0];
          row[0]                = i;
          for (unsigned int j = 1; j <= b.size(); ++j)
            {
              const unsigned int above = row[j];
              row[j]                   = std::min({row[j] + 1,
                                                   row[j - 1] + 1,
                                                   diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
              diagonal                 = above;
            }
        }
      return row[b.size()];
    }

  } // namespace



  namespace prm_names
  {
    std::string
    join(const std::vector<std::string> &parts, const std::string &separator)
    {
      std::string joined;
      for (std::size_t i = 0; i < parts.size(); ++i)
        joined += (i ? separator : "") + parts[i];
      return joined;
    }

    /// A line without its comment (deal.II's rule: from the first '#' not
    /// escaped as "\#"), trimmed.
    std::string
    strip_comment(const std::string &line)
    {
      std::size_t pos = 0;
      while ((pos = line.find('#', pos)) != std::string::npos && pos > 0 &&
             line[pos - 1] == '\\')
        ++pos;
      return Utilities::trim(line.substr(0, pos));
    }

    /// Does line start with keyword (lower or upper case) and a blank?
    bool
    starts_with_keyword(const std::string &line, const std::string &keyword)
    {
      std::string upper = keyword;
      for (char &c : upper)
        c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
      return line.size() > keyword.size() &&
             (line.compare(0, keyword.size(), keyword) == 0 ||
              line.compare(0, keyword.size(), upper) == 0) &&
             std::isspace(static_cast<unsigned char>(line[keyword.size()]));
    }

    DeclaredNames
    declared_names(const ParameterHandler &prm)
    {
      std::ostringstream text;
      prm.print_parameters(text, ParameterHandler::ShortPRM);
      DeclaredNames            names;
      std::vector<std::string> path;
      std::istringstream       in(text.str());
      for (std::string line; std::getline(in, line);)
        {
          line = strip_comment(line);
          if (starts_with_keyword(line, "subsection"))
            {
              path.push_back(Utilities::trim(line.substr(10)));
              names.subsections.push_back(join(path, "/"));
            }
          else if (line == "end" && !path.empty())
            path.pop_back();
          else if (starts_with_keyword(line, "set"))
            {
              std::vector<std::string> components = path;
              components.push_back(
                Utilities::trim(line.substr(3, line.find('=') - 3)));
              names.entries[join(components, "/")] = components;
            }
        }
      return names;
    }

    /// The candidate closest to given, if close enough to be a misspelling.
    std::string
    closest(const std::string              &given,
            const std::vector<std::string> &candidates)
    {
      const unsigned int limit =
        std::max<unsigned int>(2, static_cast<unsigned int>(given.size()) / 3);
      std::string  best;
      unsigned int best_distance = limit + 1;
      for (const std::string &candidate : candidates)
        {
          const unsigned int d = edit_distance(given, candidate);
          if (d < best_distance)
            {
              best          = candidate;
              best_distance = d;
            }
        }
      return best;
    }

    std::string
    did_you_mean(const std::string &suggestion)
    {
      return suggestion.empty() ? "" : " (did you mean '" + suggestion + "'?)";
    }

    /**
     * The suggestion for an undeclared entry `name` in subsection `path`:
     * the closest entry of that subsection, else an entry of that name (or
     * close to it) in another subsection, by full path.
     */
    std::string
    suggest_entry(const DeclaredNames &names,
                  const std::string   &path,
                  const std::string   &name)
    {
      std::vector<std::string> here, full, last;
      for (const auto &[full_path, components] : names.entries)
        {
          const std::string section =
            full_path.substr(0, full_path.size() - components.back().size());
          if (section == (path.empty() ? "" : path + "/"))
            here.push_back(components.back());
          full.push_back(full_path);
          last.push_back(components.back());
        }
      std::string suggestion = closest(name, here);
      if (suggestion.empty())
        {
          const std::string near = closest(name, last);
          for (std::size_t i = 0; i < last.size() && !near.empty(); ++i)
            if (last[i] == near)
              return full[i];
        }
      return suggestion;
    }

  } // namespace prm_names
} // namespace fgimpact
