// The Study subsection and the expansion of its entries into cases (the
// rest of a study is in study.cc).

#include <deal.II/base/utilities.h>

#include <fgimpact/base/parameter_table.h>
#include <fgimpact/base/selection.h>
#include <fgimpact/problem/study_parameters.h>

#include <algorithm>
#include <set>
#include <sstream>

namespace fgimpact
{
  namespace
  {
    /// The names of Study/Combination.
    const SelectionTable<StudyParameters::Combination> &
    combination_names()
    {
      using C                              = StudyParameters::Combination;
      static const SelectionTable<C> names = {{"product", C::product},
                                              {"zip", C::zip}};
      return names;
    }

    /// The names of Study/Method.
    const SelectionTable<StudyParameters::Method> &
    method_names()
    {
      using M                              = StudyParameters::Method;
      static const SelectionTable<M> names = {{"auto", M::automatic},
                                              {"time loop", M::time_loop}};
      return names;
    }
  } // namespace


  namespace
  {
    /// The entries of StudyParameters that set a member as they stand.
    const ParameterTable<StudyParameters> &
    study_table()
    {
      using P                              = StudyParameters;
      static const ParameterTable<P> table = [] {
        ParameterTable<P> t;
        t.add("Combination",
              &P::combination,
              combination_names(),
              "product: every combination of the lists (the first "
              "entry varies slowest). zip: the i-th case takes the "
              "i-th value of every list (all lists equally long).");
        t.add(
          "Method",
          &P::method,
          method_names(),
          "auto: cases that share the plate and differ only in the impactor, "
          "the contact law's constants or Newton's control run as "
          "convolutions of the plate's unit response (Hertz node contact, "
          "implicit Newmark with beta = 1/4, gamma = 1/2, no VTU), the others "
          "through the time loop (logged). time loop: every case through the "
          "normal time loop.");
        t.add("Write VTU",
              &P::write_vtu,
              Patterns::Bool(),
              "false: the cases write no VTU (Output/VTU interval "
              "= 0, so that they can run by convolution); "
              "--study-case K reruns one case with the input's "
              "VTU output. true: the input's VTU interval (time "
              "loop).");
        return t;
      }();
      return table;
    }
  } // namespace



  void
  StudyParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Study");
    {
      std::string entries;
      for (const std::string &entry : StudyParameters().entries)
        entries += (entries.empty() ? "" : "; ") + entry;
      prm.declare_entry(
        "Entries",
        entries,
        Patterns::Anything(),
        "The entries a parameter study varies, separated by ';', each "
        "'Section/Entry = v1, v2, ...' (nested subsections joined by '/'), "
        "e.g. 'Impactor/Initial velocity = 1, 2, 3, 4'. Empty: no study, "
        "one run. Each case writes a normal output directory "
        "Directory/case_NNN and Directory/study.csv gathers their "
        "summaries. The command-line option --study appends to this list.");
      study_table().declare(prm);
    }
    prm.leave_subsection();
  }



  void
  StudyParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Study");
    entries.clear();
    for (const auto &entry :
         Utilities::split_string_list(prm.get("Entries"), ';'))
      if (!entry.empty())
        entries.push_back(entry);
    study_table().parse(prm, *this);
    prm.leave_subsection();
    n_file_entries = entries.size();
  }



  void
  StudyParameters::append_command_line(
    const std::vector<std::string> &study_options)
  {
    entries.insert(entries.end(), study_options.begin(), study_options.end());
  }



  std::string
  StudyParameters::origin(const std::size_t i) const
  {
    return i < n_file_entries ? "Study/Entries" : "--study";
  }



  namespace
  {
    /// Study entry i split into its path and its values, checked against
    /// the paths before it (bad input throws, naming the entry).
    std::pair<std::string, std::vector<std::string>>
    split_study_entry(const StudyParameters          &study,
                      const std::size_t               i,
                      const std::vector<std::string> &paths)
    {
      const std::string &entry = study.entries[i];
      const std::string  where = study.origin(i) + ": '";
      const auto         eq    = entry.find('=');
      AssertThrow(eq != std::string::npos && eq > 0,
                  ExcMessage(where + entry +
                             "' is not 'Section/Entry = v1, v2, ...'"));
      const std::string path = Utilities::trim(entry.substr(0, eq));
      AssertThrow(std::find(paths.begin(), paths.end(), path) == paths.end(),
                  ExcMessage(where + path +
                             "' is listed twice (the second list would "
                             "replace the first); give it once."));
      // Each case writes into Output/Directory/case_NNN of the study's own
      // directory: a varied directory would be overridden silently.
      AssertThrow(path != "Output/Directory" && path != "Study/Entries",
                  ExcMessage(where + path +
                             "' cannot vary in a study: each case writes "
                             "into case_NNN of the study's Output/Directory "
                             "(run separate studies for separate "
                             "directories)."));
      const std::vector<std::string> list =
        Utilities::split_string_list(entry.substr(eq + 1), ',');
      AssertThrow(!list.empty() && !path.empty(),
                  ExcMessage(where + entry + "' has no values"));
      return {path, list};
    }
  } // namespace



  std::vector<StudyCase>
  expand_study(const StudyParameters &study)
  {
    std::vector<std::string>              paths;
    std::vector<std::string>              origins;
    std::vector<std::vector<std::string>> lists;
    for (std::size_t i = 0; i < study.entries.size(); ++i)
      {
        auto [path, list] = split_study_entry(study, i, paths);
        paths.push_back(path);
        origins.push_back(study.origin(i));
        lists.push_back(list);
      }
    std::vector<StudyCase> cases;
    if (paths.empty())
      return cases;
    if (study.combination == StudyParameters::Combination::zip)
      {
        for (const auto &list : lists)
          AssertThrow(list.size() == lists[0].size(),
                      ExcMessage("Study/Combination = zip: the lists of "
                                 "Study/Entries differ in length"));
        for (std::size_t i = 0; i < lists[0].size(); ++i)
          {
            StudyCase c;
            c.paths   = paths;
            c.origins = origins;
            for (const auto &list : lists)
              c.values.push_back(list[i]);
            cases.push_back(c);
          }
        return cases;
      }
    // Cartesian product, the last entry varying fastest.
    std::vector<std::size_t> index(paths.size(), 0);
    while (true)
      {
        StudyCase c;
        c.paths   = paths;
        c.origins = origins;
        for (std::size_t e = 0; e < paths.size(); ++e)
          c.values.push_back(lists[e][index[e]]);
        cases.push_back(c);
        std::size_t e = paths.size();
        while (e > 0 && ++index[e - 1] == lists[e - 1].size())
          index[--e] = 0;
        if (e == 0)
          return cases;
      }
  }
} // namespace fgimpact
