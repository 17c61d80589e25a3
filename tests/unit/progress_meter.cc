// The progress lines (ProgressMeter) of a fixed End time and of End time =
// auto, whose end is expected, not known (issue 41: the ETA counted to the
// Maximum end time, 2 ms, for a run that ends at 158 us).  The wall-clock
// figures are cut off; what is checked is where the lines come and what
// they count to, against the rule written out here:
//  (1) a fixed end of 400 steps: a line at each tenth, 40, 80, ..., 400,
//      "of 400", percentages 10 .. 100;
//  (2) End time = auto, at most 2000 steps, 160 expected: "of about 160"
//      at 16, 32, ..., 144; passing 160 the target grows by half (240),
//      then to 360, so a run that ends at 300 steps never prints a
//      percentage above 100 nor counts to 2000;
//  (3) a resumed run (first call at step 100 of 400) prints no tenth it
//      passed before, and its ETA counts from the resumed step.

#include <fgimpact/base/logger.h>

#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

namespace fgimpact_unit_tests::progress_meter
{
  using namespace fgimpact;

  namespace
  {
    /// The (percent, step, target) of each progress line of a run from
    /// step `first` to `last`, and whether each target said "about".
    struct Line
    {
      unsigned int percent, step, target;
      bool         about;
    };

    std::vector<Line>
    lines_of(ProgressMeter     &meter,
             const unsigned int first,
             const unsigned int last)
    {
      std::ostringstream out;
      for (unsigned int step = first; step <= last; ++step)
        meter.update(step, out);
      std::vector<Line>  lines;
      std::istringstream in(out.str());
      for (std::string text; std::getline(in, text);)
        {
          Line              l{};
          char              word[16] = {};
          const int         n        = std::sscanf(text.c_str(),
                                    "  progress %u %% step %u of %15s",
                                    &l.percent,
                                    &l.step,
                                    word);
          const std::string of       = word;
          l.about                    = of == "about";
          if (n == 3)
            {
              const std::size_t at = text.find(l.about ? "about " : "of ");
              l.target             = static_cast<unsigned int>(
                std::stoul(text.substr(at + (l.about ? 6 : 3))));
              lines.push_back(l);
            }
        }
      return lines;
    }

    /// Print the lines' steps and targets; compare with `steps` and
    /// `targets`.
    bool
    check(const char                      *what,
          const std::vector<Line>         &lines,
          const std::vector<unsigned int> &steps,
          const std::vector<unsigned int> &targets,
          const bool                       about)
    {
      bool ok = lines.size() == steps.size();
      std::printf("%s: %zu lines at steps", what, lines.size());
      for (unsigned int i = 0; i < lines.size(); ++i)
        {
          std::printf(" %u/%s%u",
                      lines[i].step,
                      about ? "~" : "",
                      lines[i].target);
          ok = ok && i < steps.size() && lines[i].step == steps[i] &&
               lines[i].target == targets[i] && lines[i].about == about &&
               lines[i].percent == 100 * steps[i] / targets[i] &&
               lines[i].percent <= 100;
        }
      std::printf(": %s\n", ok ? "yes" : "NO");
      return ok;
    }
  } // namespace



  int
  test_main(int, char **)
  {
    bool ok = true;
    {
      ProgressMeter             fixed(400, true);
      std::vector<unsigned int> steps, targets;
      for (unsigned int k = 1; k <= 10; ++k)
        steps.push_back(40 * k), targets.push_back(400);
      ok = check("(1) End time 400 steps",
                 lines_of(fixed, 0, 400),
                 steps,
                 targets,
                 false) &&
           ok;
    }
    {
      ProgressMeter automatic(2000, true, 160);
      // 160 expected: tenths at 16 .. 144; at 160 the target becomes 240
      // (its tenths from the 7th: 168, 192, 216); at 240 it becomes 360
      // (from the 7th: 252, 288).
      const std::vector<unsigned int> steps = {
        16, 32, 48, 64, 80, 96, 112, 128, 144, 168, 192, 216, 252, 288};
      std::vector<unsigned int> targets(9, 160);
      targets.insert(targets.end(), {240, 240, 240, 360, 360});
      ok = check("(2) End time = auto, 160 steps expected, ends at 300",
                 lines_of(automatic, 0, 300),
                 steps,
                 targets,
                 true) &&
           ok;
    }
    {
      ProgressMeter resumed(400, true);
      ok = check("(3) resumed at step 100 of 400",
                 lines_of(resumed, 100, 400),
                 {120, 160, 200, 240, 280, 320, 360, 400},
                 std::vector<unsigned int>(8, 400),
                 false) &&
           ok;
    }
    std::printf("%s\n", ok ? "all checks passed" : "SOME CHECKS FAILED");
    return ok ? 0 : 1;
  }
} // namespace fgimpact_unit_tests::progress_meter
