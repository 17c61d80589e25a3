#ifndef fgimpact_selection_h
#define fgimpact_selection_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/patterns.h>

#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

namespace fgimpact
{
  using namespace dealii;

  /**
   * The names of a Patterns::Selection and the enum values they map to,
   * written once per selection: the pattern for declare_entry(), the value
   * for parse_parameters() and the name back for summary.txt and the log.
   * Adding an alternative is then one line here plus its case in the
   * component's factory.
   */
  template <typename Enum>
  class SelectionTable
  {
  public:
    SelectionTable(std::initializer_list<std::pair<const char *, Enum>> table)
    {
      for (const auto &entry : table)
        entries.emplace_back(entry.first, entry.second);
    }

    /// "first|second|...", in the table's order.
    Patterns::Selection
    pattern() const
    {
      std::string names;
      for (const auto &entry : entries)
        names += (names.empty() ? "" : "|") + entry.first;
      return Patterns::Selection(names);
    }

    /// The value named `name` (which the pattern has accepted).
    Enum
    value(const std::string &name) const
    {
      for (const auto &entry : entries)
        if (entry.first == name)
          return entry.second;
      AssertThrow(false, ExcMessage("unknown selection '" + name + "'"));
      return entries.front().second;
    }

    /// The name of `value`.
    const std::string &
    name(const Enum value) const
    {
      for (const auto &entry : entries)
        if (entry.second == value)
          return entry.first;
      AssertThrow(false, ExcMessage("a selection value without a name"));
      return entries.front().first;
    }

  private:
    std::vector<std::pair<std::string, Enum>> entries;
  };
} // namespace fgimpact

#endif
