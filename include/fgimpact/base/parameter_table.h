#ifndef fgimpact_parameter_table_h
#define fgimpact_parameter_table_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/patterns.h>

#include <fgimpact/base/selection.h>

#include <functional>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

namespace fgimpact
{
  using namespace dealii;

  /// A default for the listing: the shortest decimal that reads back as
  /// the same double: plain in [1e-4, 1e6) ("0.2"), else engineering
  /// notation where it pads at most one zero ("70e9", "3e8", "1e-6").
  std::string
  prm_string(const double value);

  std::string
  prm_string(const unsigned int value);

  std::string
  prm_string(const int value);

  /// "true" or "false".
  std::string
  prm_string(const bool value);

  std::string
  prm_string(const std::string &value);

  /**
   * The entries of one component's subsection, each declared once: its
   * name, the member of the component's Parameters struct P it sets, its
   * pattern and its help.  The default is that member in a
   * default-constructed P (the member initializer is the one place a
   * default is written), so the listing, parse_parameters() and a P built
   * in code agree by construction.  A selection maps its names to an enum
   * member through its SelectionTable.  Entries whose value is not a
   * member as it stands (a unit conversion, `auto` beside a number) are
   * declared by hand beside the table.
   */
  template <typename P>
  class ParameterTable
  {
  public:
    /// A double, unsigned int, int, bool or std::string member.
    template <typename T>
    ParameterTable &
    add(const std::string &name,
        T P::                       *member,
        const Patterns::PatternBase &pattern,
        const std::string           &help)
    {
      rows.push_back({name,
                      pattern.clone(),
                      help,
                      [member](const P &p) { return prm_string(p.*member); },
                      [member, name](const ParameterHandler &prm, P &p) {
                        if constexpr (std::is_same_v<T, double>)
                          p.*member = prm.get_double(name);
                        else if constexpr (std::is_same_v<T, bool>)
                          p.*member = prm.get_bool(name);
                        else if constexpr (std::is_same_v<T, std::string>)
                          p.*member = prm.get(name);
                        else
                          {
                            static_assert(std::is_integral_v<T>,
                                          "a member of an unsupported type");
                            p.*member = static_cast<T>(prm.get_integer(name));
                          }
                      }});
      return *this;
    }

    /// An enum member named by a selection (its pattern and names).
    template <typename E>
    ParameterTable &
    add(const std::string &name,
        E P::                   *member,
        const SelectionTable<E> &names,
        const std::string       &help)
    {
      rows.push_back(
        {name,
         names.pattern().clone(),
         help,
         [member, &names](const P &p) { return names.name(p.*member); },
         [member, name, &names](const ParameterHandler &prm, P &p) {
           p.*member = names.value(prm.get(name));
         }});
      return *this;
    }

    /// Declare every entry in the subsection prm has entered.
    void
    declare(ParameterHandler &prm) const
    {
      const P defaults{};
      for (const Row &row : rows)
        prm.declare_entry(row.name, row.get(defaults), *row.pattern, row.help);
    }

    /// Set the members of p from prm (in the same subsection).
    void
    parse(const ParameterHandler &prm, P &p) const
    {
      for (const Row &row : rows)
        row.set(prm, p);
    }

  private:
    struct Row
    {
      std::string                                        name;
      std::unique_ptr<Patterns::PatternBase>             pattern;
      std::string                                        help;
      std::function<std::string(const P &)>              get;
      std::function<void(const ParameterHandler &, P &)> set;
    };
    std::vector<Row> rows;
  };
} // namespace fgimpact

#endif
