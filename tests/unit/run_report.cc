// report.html (Output/Report, scripts/report.py), read back as a user's
// browser would (issue 41), on a small resolved-sphere run with J2 plasticity
// and a 2-case study:
//  (1) the file is self-contained: no reference to another file or
//      server (no src= but data: URIs, no http);
//  (2) every headline number in its table equals summary.txt's value of
//      the key the row names (to its 6 printed digits), and at least the
//      peak force, duration, departure velocity and deflection are there;
//  (2b) its validity list holds summary.txt's verdicts, one item each;
//  (3) the contact-force chart draws one point per history.csv row, and
//      the peak of the drawn curve, mapped back through the chart's axis
//      ticks, is history.csv's largest force (to 1 % of the axis span);
//  (4) the manifest lists report.html, so Output/Overwrite cleans it;
//  (5) a study's report has one row per study.csv case, each linking a
//      report.html that exists;
//  (6) without python3 on PATH the run still completes (exit code 0), says
//      why in one note line, and writes no report.html.

#include <fgimpact/base/files.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <regex>
#include <sstream>
#include <test_tools.h>

namespace fgimpact_unit_tests::run_report
{
  namespace
  {
    namespace fs = std::filesystem;
    using fgimpact_tests::read_text;

    const std::string scene =
      std::string(FGIMPACT_SOURCE_DIR) + "/tests/run/default_small.prm";

    /// Run the executable with these arguments; its exit code (stdout to
    /// `log`).
    int
    run(const std::string &arguments,
        const std::string &log,
        const std::string &environment = "")
    {
      const std::string command = environment + " " FGIMPACT_EXECUTABLE " " +
                                  scene + " " + arguments + " > " + log +
                                  " 2>&1";
      const int status = std::system(command.c_str());
      return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    }

    /// (1)
    bool
    self_contained(const std::string &html)
    {
      const std::regex source(R"(src="([^"]*))");
      bool             ok = true;
      for (auto it = std::sregex_iterator(html.begin(), html.end(), source);
           it != std::sregex_iterator();
           ++it)
        ok = ok && (*it)[1].str().rfind("data:", 0) == 0;
      // The only URL: SVG's namespace name, which is never fetched.
      const std::string without_namespace =
        std::regex_replace(html,
                           std::regex("http://www\\.w3\\.org/2000/svg"),
                           "");
      ok = ok && without_namespace.find("http") == std::string::npos;
      std::printf("(1) self-contained (no src but data:, no http): %s\n",
                  ok ? "yes" : "NO");
      return ok;
    }

    /// (2): the rows' (value, key); the number checked against summary.txt.
    bool
    headline_numbers(const std::string &html, const std::string &summary)
    {
      const auto       values = fgimpact_tests::read_summary(summary);
      const std::regex row(
        R"(<td class=n>([^<]*)</td><td>[^<]*</td><td>.*?</td><td><code>([a-z_0-9A-Z.]+)</code>)");
      unsigned int n = 0, bad = 0, required = 0;
      for (auto it = std::sregex_iterator(html.begin(), html.end(), row);
           it != std::sregex_iterator();
           ++it, ++n)
        {
          const std::string key   = (*it)[2];
          const double      shown = std::stod((*it)[1]);
          const auto        found = values.find(key);
          const double      value =
            found == values.end() ? NAN : std::stod(found->second);
          if (!(std::abs(shown - value) <= 5e-6 * std::abs(value)))
            {
              ++bad;
              std::printf("  %s: report %g, summary.txt %g\n",
                          key.c_str(),
                          shown,
                          value);
            }
          for (const char *k : {"peak_contact_force_N",
                                "contact_duration_us",
                                "departure_velocity_m_s",
                                "max_midplane_deflection_um"})
            required += key == k;
        }
      std::printf("(2) %u headline numbers, each equal to summary.txt's "
                  "value of its key to 6 digits: %s; the four main ones "
                  "there: %s\n",
                  n,
                  bad == 0 ? "yes" : "NO",
                  required == 4 ? "yes" : "NO");
      return bad == 0 && n >= 4 && required == 4;
    }

    /// (2b) The validity list against summary.txt's validity line: every
    /// item is a verdict of the line, and every verdict of the line (its
    /// "; "-separated items outside parentheses) is an item.
    bool
    validity_items(const std::string &html, const std::string &summary)
    {
      std::string  line     = fgimpact_tests::read_summary(summary)["validity"];
      unsigned int expected = line.empty() ? 0 : 1, depth = 0;
      for (std::size_t i = 0; i < line.size(); ++i)
        {
          depth += line[i] == '(' ? 1 : 0;
          depth -= line[i] == ')' ? 1 : 0;
          if (depth == 0 &&
              (line.compare(i, 2, "; ") == 0 || line.compare(i, 3, " | ") == 0))
            ++expected;
        }
      const std::regex item("<li><b>(breaks|holds)</b>: (.*?)</li>");
      unsigned int     n = 0, found = 0;
      for (auto it = std::sregex_iterator(html.begin(), html.end(), item);
           it != std::sregex_iterator();
           ++it, ++n)
        {
          const std::string text =
            std::regex_replace((*it)[2].str(), std::regex("&#x27;"), "'");
          found += line.find(text) != std::string::npos;
        }
      const bool ok = n == expected && found == n && n > 0;
      std::printf("(2b) %u validity items for the %u verdicts of summary.txt's "
                  "validity line, each its text: %s\n",
                  n,
                  expected,
                  ok ? "yes" : "NO");
      return ok;
    }

    /// (3) The contact-force chart against history.csv.
    bool
    force_chart(const std::string &html, const std::string &history)
    {
      const std::size_t start = html.find("Contact force</text>");
      const std::size_t end   = html.find("</svg>", start);
      if (start == std::string::npos || end == std::string::npos)
        {
          std::printf("(3) no contact-force chart: NO\n");
          return false;
        }
      const std::string chart = html.substr(start, end - start);
      // The y ticks: <text x=.. y="Y" text-anchor="end">VALUE</text>, Y
      // 4 px below the tick's line.
      const std::regex tick(
        R"re(<text x="[0-9.]+" y="([-0-9.]+)" text-anchor="end">([-0-9.e+]+)</text>)re");
      std::vector<std::pair<double, double>> ticks; // (pixel, value)
      for (auto it = std::sregex_iterator(chart.begin(), chart.end(), tick);
           it != std::sregex_iterator();
           ++it)
        ticks.emplace_back(std::stod((*it)[1]) - 4, std::stod((*it)[2]));
      std::smatch points;
      std::regex_search(chart, points, std::regex(R"re(points="([^"]*)")re"));
      std::istringstream in(points[1].str());
      unsigned int       n_points = 0;
      double             top      = 1e30; // the smallest pixel y
      for (std::string xy; in >> xy; ++n_points)
        top = std::min(top, std::stod(xy.substr(xy.find(',') + 1)));
      // history.csv: rows and the largest contact_force_N (column 2).
      std::istringstream rows(read_text(history));
      std::string        line;
      std::getline(rows, line);
      unsigned int n_rows  = 0;
      double       largest = 0;
      for (; std::getline(rows, line); ++n_rows)
        largest = std::max(largest, std::stod(line.substr(line.find(',') + 1)));
      if (ticks.size() < 2)
        return false;
      const auto &[y0, v0] = ticks.front();
      const auto &[y1, v1] = ticks.back();
      const double drawn   = v0 + (top - y0) * (v1 - v0) / (y1 - y0);
      const bool   ok      = n_points == n_rows &&
                      std::abs(drawn - largest) <= 0.01 * std::abs(v1 - v0);
      std::printf("(3) contact-force chart: %u points for %u history rows; "
                  "its peak read off the axis equal to history.csv's largest "
                  "force to 1 %% of the axis: %s\n",
                  n_points,
                  n_rows,
                  ok ? "yes" : "NO");
      return ok;
    }

    /// (5) A study's rows and their links.
    bool
    study_rows(const std::string &directory)
    {
      const std::string html = read_text(directory + "/report.html");
      const std::regex  link(R"re(<td><a href="([^"]+)">)re");
      unsigned int      n = 0, existing = 0;
      for (auto it = std::sregex_iterator(html.begin(), html.end(), link);
           it != std::sregex_iterator();
           ++it, ++n)
        existing += (*it)[1].str().find("report.html") != std::string::npos &&
                    fs::exists(directory + "/" + (*it)[1].str());
      std::istringstream csv(read_text(directory + "/study.csv"));
      unsigned int       cases = 0;
      for (std::string line; std::getline(csv, line);)
        ++cases;
      --cases; // the header
      const bool ok = n == cases && existing == cases && cases == 2;
      std::printf("(5) study: %u rows for %u cases of study.csv, %u linking "
                  "an existing report.html: %s\n",
                  n,
                  cases,
                  existing,
                  ok ? "yes" : "NO");
      return ok;
    }
  } // namespace



  int
  test_main(int, char **)
  {
    bool              ok     = true;
    const std::string common = "-s 'Contact/Model=resolved sphere' "
                               "-s 'Geometry/Contact refinement levels=2' "
                               "-s 'Material/Plasticity=J2' "
                               "-s 'Time integration/End time=auto' "
                               "-s 'Output/Print timing=false' ";
    fs::remove_all("report_out");
    const int code = run(common + "-s Output/Directory=report_out", "run.log");
    const std::string html = read_text("report_out/report.html");
    std::printf("a resolved run: exit code %d, report.html written %s\n",
                code,
                html.empty() ? "NO" : "yes");
    ok = ok && code == 0 && !html.empty();
    ok = self_contained(html) && ok;
    ok = headline_numbers(html, "report_out/summary.txt") && ok;
    ok = validity_items(html, "report_out/summary.txt") && ok;
    ok = force_chart(html, "report_out/history.csv") && ok;
    const bool listed =
      fgimpact::read_manifest("report_out").count("report.html") == 1;
    std::printf("(4) the manifest lists report.html: %s\n",
                listed ? "yes" : "NO");
    ok = ok && listed;

    fs::remove_all("report_study");
    const int study = run("--study 'Impactor/Initial velocity=1,2' "
                          "-s Output/Directory=report_study",
                          "study.log");
    ok              = study == 0 && study_rows("report_study") && ok;

    fs::remove_all("report_none");
    const int          bare = run(common + "-s Output/Directory=report_none",
                         "bare.log",
                         "PATH=/nonexistent");
    std::string        note;
    unsigned int       n_notes = 0;
    std::istringstream log(read_text("bare.log"));
    for (std::string line; std::getline(log, line);)
      if (line.find("report.html not written") != std::string::npos)
        ++n_notes, note = line;
    const bool none = !fs::exists("report_none/report.html");
    std::printf("(6) no python3 on PATH: exit code %d, one note line %s, no "
                "report.html %s\n",
                bare,
                n_notes == 1 ? "yes" : "NO",
                none ? "yes" : "NO");
    ok = ok && bare == 0 && n_notes == 1 && none &&
         fs::exists("report_none/summary.txt");
    std::printf("%s\n", ok ? "all checks passed" : "SOME CHECKS FAILED");
    return ok ? 0 : 1;
  }
} // namespace fgimpact_unit_tests::run_report
