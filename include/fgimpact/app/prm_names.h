#ifndef fgimpact_prm_names_h
#define fgimpact_prm_names_h

#include <deal.II/base/parameter_handler.h>

#include <map>
#include <string>
#include <vector>

namespace fgimpact
{
  using namespace dealii;

  /**
   * The names a ParameterHandler declares, and the nearest of them to a
   * misspelt one: what InputFile reads .prm lines with and how its
   * one-line errors suggest an entry ("did you mean ...?").
   */
  namespace prm_names
  {
    /// parts joined by separator.
    std::string
    join(const std::vector<std::string> &parts, const std::string &separator);

    /// A line without its comment (deal.II's rule: from the first '#' not
    /// escaped as "\#"), trimmed.
    std::string
    strip_comment(const std::string &line);

    /// Does line start with keyword (lower or upper case) and a blank?
    bool
    starts_with_keyword(const std::string &line, const std::string &keyword);

    /// Every declared entry and subsection, by full path ("A/B/name").
    struct DeclaredNames
    {
      std::map<std::string, std::vector<std::string>> entries;
      std::vector<std::string>                        subsections;
    };

    DeclaredNames
    declared_names(const ParameterHandler &prm);

    /// The candidate closest to given, if close enough to be a misspelling
    /// (edit distance, ignoring case); empty if none is.
    std::string
    closest(const std::string              &given,
            const std::vector<std::string> &candidates);

    /// " (did you mean 'suggestion'?)", or empty.
    std::string
    did_you_mean(const std::string &suggestion);

    /**
     * The suggestion for an undeclared entry `name` in subsection `path`:
     * the closest entry of that subsection, else an entry of that name (or
     * close to it) in another subsection, by full path.
     */
    std::string
    suggest_entry(const DeclaredNames &names,
                  const std::string   &path,
                  const std::string   &name);
  } // namespace prm_names
} // namespace fgimpact

#endif
