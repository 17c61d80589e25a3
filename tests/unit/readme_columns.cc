// README.md's table of the history.csv columns lists exactly the columns
// the program writes (history_columns(), then the resolved contact's
// contact_area_columns()), in the order of the file: the table is read
// from the README a user reads, not kept in sync by hand.

#include <fgimpact/output/monitor.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

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
        if (line.rfind("| column |", 0) == 0)
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
main()
{
  std::ifstream      file(std::string(FGIMPACT_SOURCE_DIR) + "/README.md");
  std::ostringstream text;
  text << file.rdbuf();
  const auto documented = table_names(text.str(), "### history.csv columns");

  std::vector<std::string> written;
  for (const auto &c : fgimpact::history_columns())
    written.push_back(c.name);
  for (const auto &c : fgimpact::contact_area_columns())
    written.push_back(c.name);

  bool same = documented == written;
  std::printf("history.csv: %zu columns written, %zu in README.md's table\n",
              written.size(),
              documented.size());
  for (std::size_t i = 0; i < std::max(written.size(), documented.size()); ++i)
    {
      const std::string w = i < written.size() ? written[i] : "(none)";
      const std::string d = i < documented.size() ? documented[i] : "(none)";
      if (w != d)
        std::printf("  column %zu: written %s, documented %s\n",
                    i + 1,
                    w.c_str(),
                    d.c_str());
    }
  std::printf("README.md documents every history.csv column, in order: %s\n",
              same ? "yes" : "NO");
  std::printf("%s\n", same ? "all checks passed" : "SOME CHECKS FAILED");
  return same ? 0 : 1;
}
