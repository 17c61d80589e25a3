// doc/outputs.md's table (the README's until 2026-11) of the history.csv
// columns lists exactly the columns
// the program writes (history_columns(), then the resolved contact's
// contact_area_columns()), in the order of the file; its table of the
// impact summary.txt keys lists exactly impact_summary_keys() (as a set:
// the table groups related keys).  The tables are read from the page a
// user reads, not kept in sync by hand.

#include <fgimpact/output/impact_summary.h>
#include <fgimpact/output/monitor.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace fgimpact_unit_tests::readme_columns
{

  namespace
  {
    /// The backquoted names in the first cell of each row of the first
    /// table after `heading` ("`a`, `b`" gives a and b).
    std::vector<std::string>
    table_names(const std::string &readme, const std::string &heading)
    {
      std::vector<std::string> names;
      std::istringstream       in(readme.substr(readme.find(heading)));
      std::string              line;
      bool                     in_table = false;
      while (std::getline(in, line))
        {
          if (line.rfind("| column |", 0) == 0 || line.rfind("| key |", 0) == 0)
            {
              in_table = true;
              continue;
            }
          if (!in_table || line.rfind("|---", 0) == 0)
            continue;
          if (line.rfind("|", 0) != 0)
            break;
          const std::string cell = line.substr(1, line.find('|', 1) - 1);
          for (std::size_t at = cell.find('`'); at != std::string::npos;)
            {
              const std::size_t end = cell.find('`', at + 1);
              names.push_back(cell.substr(at + 1, end - at - 1));
              at = cell.find('`', end + 1);
            }
        }
      return names;
    }
  } // namespace

  int
  test_main(int, char **)
  {
    std::ifstream      file(std::string(FGIMPACT_SOURCE_DIR) +
                              "/doc/outputs.md");
    std::ostringstream text;
    text << file.rdbuf();
    const auto documented = table_names(text.str(), "## history.csv columns");

    std::vector<std::string> written;
    for (const auto &c : fgimpact::history_columns())
      written.push_back(c.name);
    for (const auto &c : fgimpact::contact_area_columns())
      written.push_back(c.name);
    for (const auto &c : fgimpact::plasticity_columns())
      written.push_back(c.name);

    bool same = documented == written;
    std::printf("history.csv: %zu columns written, %zu in doc/outputs.md's table\n",
                written.size(),
                documented.size());
    for (std::size_t i = 0; i < std::max(written.size(), documented.size());
         ++i)
      {
        const std::string w = i < written.size() ? written[i] : "(none)";
        const std::string d = i < documented.size() ? documented[i] : "(none)";
        if (w != d)
          std::printf("  column %zu: written %s, documented %s\n",
                      i + 1,
                      w.c_str(),
                      d.c_str());
      }
    std::printf("doc/outputs.md documents every history.csv column, in order: %s\n",
                same ? "yes" : "NO");

    const auto table =
      table_names(text.str(), "## summary.txt keys (impact runs)");
    const std::set<std::string> keys_documented(table.begin(), table.end());
    std::set<std::string>       keys_written;
    for (const auto &key : fgimpact::impact_summary_keys())
      keys_written.insert(key.name);
    std::printf("summary.txt (impact): %zu keys written, %zu in doc/outputs.md's "
                "table\n",
                keys_written.size(),
                keys_documented.size());
    for (const auto &key : keys_written)
      if (keys_documented.count(key) == 0)
        std::printf("  written, not documented: %s\n", key.c_str());
    for (const auto &key : keys_documented)
      if (keys_written.count(key) == 0)
        std::printf("  documented, not written: %s\n", key.c_str());
    const bool same_keys = keys_documented == keys_written;
    std::printf("doc/outputs.md documents every summary.txt key: %s\n",
                same_keys ? "yes" : "NO");
    const bool ok = same && same_keys;
    std::printf("%s\n", ok ? "all checks passed" : "SOME CHECKS FAILED");
    return ok ? 0 : 1;
  }
} // namespace fgimpact_unit_tests::readme_columns
