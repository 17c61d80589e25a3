#ifndef fgimpact_problem_study_parameters_h
#define fgimpact_problem_study_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace fgimpact
{
  using namespace dealii;

  /**
   * Subsection "Study": a parameter study, i.e. the same input run for
   * several values of one or more entries.  Each varied entry is a list,
   *   set Entries = Impactor/Initial velocity = 1, 2, 3, 4; Impactor/Density
   *                 = 7800, 8900
   * (entries separated by ';', values by ','), combined as a cartesian
   * product (first entry outermost) or element by element (zip).  On the
   * command line `--study "Impactor/Initial velocity=1,2,3,4"` (repeatable)
   * appends to Entries.  Empty Entries: no study, a normal run.
   */
  struct StudyParameters
  {
    enum class Combination
    {
      product,
      zip
    };
    enum class Method
    {
      automatic, // convolution where it applies, the time loop elsewhere
      time_loop  // every case through the normal time loop
    };

    std::vector<std::string> entries; // "Section/Entry = v1, v2, ..."
    /// entries[0, n_file_entries) come from Study/Entries, the rest from
    /// --study: errors name where the user wrote the entry.
    std::size_t n_file_entries = 0;
    Combination combination    = Combination::product;
    Method      method         = Method::automatic;
    bool        write_vtu      = false;

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);
    /// Append the command line's --study lists.
    void
    append_command_line(const std::vector<std::string> &study_options);
    /// "--study" or "Study/Entries": where entry i was given.
    std::string
    origin(const std::size_t i) const;
  };



  /// One case of a study: its assignments "Section/Entry=value", in the
  /// order of the varied entries.
  struct StudyCase
  {
    std::vector<std::string> paths;
    std::vector<std::string> values;
    std::vector<std::string> origins; // StudyParameters::origin()

    /// "Section/Entry=value" of entry i.
    std::string
    assignment(const unsigned int i) const
    {
      return paths[i] + "=" + values[i];
    }
  };

  /// The cases of a study (throws ExcMessage naming Study/Entries on a
  /// malformed list or, for zip, lists of different lengths).
  std::vector<StudyCase>
  expand_study(const StudyParameters &study);
} // namespace fgimpact

#endif
