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
   * A kind with several classes is a Registry (below): name, help and
   * factory in one row.
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

    virtual ~SelectionTable() = default;

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

  protected:
    SelectionTable() = default;

    std::vector<std::pair<std::string, Enum>> entries;
  };



  /**
   * The alternatives of one kind (gradation laws, contact models, time
   * schemes) in one table, ASPECT's plugin lists in spirit: each row is
   * the name, the enum value, the help text and the factory, so that a new
   * alternative is its class and one row (no static self-registration: a
   * table in the kind's .cc cannot be dropped by the linker).  As a
   * SelectionTable it gives the pattern, the value and the name.
   */
  template <typename Enum, typename Factory>
  class Registry : public SelectionTable<Enum>
  {
  public:
    struct Entry
    {
      const char *name;
      Enum        value;
      /// One or more sentences, starting after "name: ".
      const char *help;
      Factory     create;
    };

    Registry(std::initializer_list<Entry> table)
      : rows(table)
    {
      for (const auto &row : rows)
        this->entries.emplace_back(row.name, row.value);
    }

    /// "name: help name: help ...", in the table's order (for the entry's
    /// help string).
    std::string
    help() const
    {
      std::string text;
      for (const auto &row : rows)
        text +=
          (text.empty() ? "" : " ") + std::string(row.name) + ": " + row.help;
      return text;
    }

    /// The factory of `value`.
    const Factory &
    factory(const Enum value) const
    {
      for (const auto &row : rows)
        if (row.value == value)
          return row.create;
      AssertThrow(false, ExcMessage("a registry value without a factory"));
      return rows.front().create;
    }

  private:
    std::vector<Entry> rows;
  };
} // namespace fgimpact

#endif
