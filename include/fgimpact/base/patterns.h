#ifndef fgimpact_patterns_h
#define fgimpact_patterns_h

#include <deal.II/base/patterns.h>

#include <memory>
#include <string>

namespace fgimpact
{
  using namespace dealii;

  /**
   * A ParameterHandler pattern for an entry that is either the keyword
   * `auto` or a number within [lower, upper] (Time integration/End time):
   * the ParameterHandler then refuses anything else with its usual error
   * naming the entry, and the listing shows both forms.
   */
  class DoubleOrAuto : public Patterns::PatternBase
  {
  public:
    DoubleOrAuto(const double lower, const double upper)
      : numbers(lower, upper)
    {}

    bool
    match(const std::string &test_string) const override
    {
      return test_string == "auto" || numbers.match(test_string);
    }

    std::string
    description(const OutputStyle style = Machine) const override
    {
      // As deal.II writes its patterns, "[Double 1e-12...1000 ...]".
      const std::string d = numbers.description(style);
      return d.empty() || d[0] != '[' ? "auto or " + d :
                                        "[auto or " + d.substr(1);
    }

    std::unique_ptr<Patterns::PatternBase>
    clone() const override
    {
      return std::make_unique<DoubleOrAuto>(*this);
    }

  private:
    Patterns::Double numbers;
  };
} // namespace fgimpact

#endif
