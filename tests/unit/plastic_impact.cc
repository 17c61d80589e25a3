// The default scene's impact with the resolved contact on a plastic metal
// face (Material/Plasticity = J2, quarter plate), against what is known
// independently of the update formulas:
//  1. The energy balance with the plastic work: E_impactor + E_kinetic +
//     E_strain + E_contact + W_plastic is conserved by the dynamics, and
//     the scheme's error in it falls with the time step at second order
//     (average acceleration); Newton tolerance 1e-8 keeps the iteration's
//     error out.  dt = 2, 1, 0.5 us at contact refinement level 3.
//  2. A yield strength no stress reaches (1e11 Pa): the plastic path gives
//     the elastic run's numbers exactly.
//  3. What users read: summary.txt's plastic_dissipation_J against the
//     last row of history.csv's energy_plastic_J, and its
//     max_equivalent_plastic_strain against the largest
//     equivalent_plastic_strain of the last VTU snapshot.
//  4. Mesh convergence (levels 3, 4, 5): the changes of the restitution,
//     the crater depth and the plastic work shrink.

#include <deal.II/base/mpi.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <test_tools.h>
#include <vtu_reader.h>

namespace fgimpact_unit_tests::plastic_impact
{

  using namespace dealii;

  namespace
  {
    /// dt (us) as seconds in the .prm, e.g. "5e-07".
    std::string
    seconds_text(const double dt_us)
    {
      char text[32];
      std::snprintf(text, sizeof(text), "%.6g", dt_us * 1e-6);
      return text;
    }


    /// The default scene, resolved, quarter, at contact refinement `levels`
    /// and time step dt (us), with the extra settings; its summary.txt.
    std::map<std::string, std::string>
    impact(const std::string &name,
           const unsigned int levels,
           const double       dt_us,
           const std::string &extra)
    {
      const std::string directory = "out_" + name;
      fgimpact_tests::remove_output(directory);
      fgimpact_tests::run_quietly(
        FGIMPACT_SOURCE_DIR "/prm/default.prm",
        "subsection Geometry\n set Symmetry = quarter\n"
        " set Contact refinement levels = " +
          std::to_string(levels) +
          "\nend\n"
          "subsection Contact\n set Model = resolved sphere\nend\n"
          "subsection Newton\n set Tolerance = 1e-8\nend\n"
          "subsection Time integration\n set Time step = " +
          seconds_text(dt_us) +
          "\n set End time = auto\nend\n"
          "subsection Output\n set Directory = " +
          directory +
          "\n set VTU interval = 0\n set Log interval = 0\n"
          " set Print timing = false\nend\n" +
          extra);
      return fgimpact_tests::read_summary(directory + "/summary.txt");
    }

    const std::string j2 = "subsection Material\n set Plasticity = J2\nend\n";

    double
    number(const std::map<std::string, std::string> &s, const std::string &key)
    {
      return std::stod(s.at(key));
    }
  } // namespace

  int
  test_main(int argc, char **argv)
  {
    Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
    bool                             ok = true;

    // 1. The energy balance.
    double drift[3];
    for (unsigned int k = 0; k < 3; ++k)
      {
        const double dt = 2. / (1 << k);
        drift[k]        = number(impact("dt" + std::to_string(k), 3, dt, j2),
                          "max_relative_energy_drift");
      }
    const double order[2] = {std::log2(drift[0] / drift[1]),
                             std::log2(drift[1] / drift[2])};
    std::printf("energy balance with the plastic work, dt = 2, 1, 0.5 us: "
                "largest relative error %.2e, %.2e, %.2e; observed order %.2f, "
                "%.2f (limit > 1.5)\n",
                drift[0],
                drift[1],
                drift[2],
                order[0],
                order[1]);
    ok = ok && order[0] > 1.5 && order[1] > 1.5;

    // 2. The elastic limit.
    const auto elastic = impact("elastic", 3, 1., "");
    const auto stiff   = impact(
      "stiff",
      3,
      1.,
      "subsection Material\n set Plasticity = J2\n set Metal yield strength "
        "= 1e11\nend\n");
    bool same = stiff.at("first_yield_time_us") == "none" &&
                number(stiff, "plastic_dissipation_J") == 0.;
    for (const std::string key : {"peak_contact_force_N",
                                  "contact_duration_us",
                                  "departure_velocity_m_s",
                                  "max_midplane_deflection_um",
                                  "max_relative_energy_drift"})
      same = same && elastic.at(key) == stiff.at(key);
    // The peak forces to 1e-6 relative (summary.txt has 3e-8: digits that
    // the CPU's round-off may change).
    std::printf("yield strength 1e11 Pa: peak force %.2f N (elastic %.2f N), "
                "the same peak force, duration, departure velocity, deflection "
                "and energy drift, no yield: %s\n",
                number(stiff, "peak_contact_force_N"),
                number(elastic, "peak_contact_force_N"),
                same ? "yes" : "NO");
    ok = ok && same;

    // 3. What users read, with a VTU snapshot every 10 steps.
    {
      const auto s = impact("files",
                            3,
                            1.,
                            j2 + "subsection Output\n set VTU interval = 10\n"
                                 " set VTU compression = none\n"
                                 " set Fields = displacement\nend\n");
      // The last row of history.csv.
      std::ifstream in("out_files/history.csv");
      std::string   header, line, last;
      std::getline(in, header);
      while (std::getline(in, line))
        last = line;
      std::vector<std::string> names, values;
      for (std::stringstream h(header); std::getline(h, line, ',');)
        names.push_back(line);
      for (std::stringstream r(last); std::getline(r, line, ',');)
        values.push_back(line);
      std::string work;
      for (unsigned int c = 0; c < names.size(); ++c)
        if (names[c] == "energy_plastic_J")
          work = values[c];
      // The last snapshot: the highest step number of vtu/solution_*.0.vtu
      // or solution_*.vtu.
      std::string snapshot;
      for (const auto &entry :
           std::filesystem::directory_iterator("out_files/vtu"))
        {
          const std::string file = entry.path().filename().string();
          if (file.rfind("solution_", 0) == 0 &&
              file.find("peak") == std::string::npos && file.size() > 4 &&
              file.substr(file.size() - 4) == ".vtu" &&
              (snapshot.empty() || file > snapshot))
            snapshot = file;
        }
      float largest = 0;
      for (const float e :
           fgimpact_tests::read_array("out_files/vtu/" + snapshot,
                                      "equivalent_plastic_strain"))
        largest = std::max(largest, e);
      const double summary_strain = number(s, "max_equivalent_plastic_strain");
      const bool   files_agree =
        work == s.at("plastic_dissipation_J") &&
        std::abs(largest - summary_strain) < 1e-6 + 1e-6 * summary_strain;
      // The plastic work to 4e-6 relative (the files have 4e-8: digits that
      // the CPU's round-off may change); the check compares the texts.
      std::printf("summary.txt plastic_dissipation_J = %.7f, history.csv's "
                  "last energy_plastic_J = %.7f; max_equivalent_plastic_strain "
                  "= %.6f, the last VTU snapshot's largest %.6f: %s\n",
                  number(s, "plastic_dissipation_J"),
                  work.empty() ? std::nan("") : std::stod(work),
                  summary_strain,
                  largest,
                  files_agree ? "agree" : "DIFFER");
      ok = ok && files_agree;
    }

    // 4. Mesh convergence.
    std::map<std::string, std::string> level[3];
    for (unsigned int k = 0; k < 3; ++k)
      level[k] = impact("level" + std::to_string(3 + k), 3 + k, 1., j2);
    for (const std::string key : {"coefficient_of_restitution",
                                  "permanent_indentation_um",
                                  "plastic_dissipation_J",
                                  "peak_contact_force_N"})
      {
        const double q[3]   = {number(level[0], key),
                               number(level[1], key),
                               number(level[2], key)};
        const bool   shrink = std::abs(q[2] - q[1]) < std::abs(q[1] - q[0]);
        std::printf("%s at levels 3, 4, 5: %.6g, %.6g, %.6g; changes %+.3g, "
                    "%+.3g: %s\n",
                    key.c_str(),
                    q[0],
                    q[1],
                    q[2],
                    q[1] - q[0],
                    q[2] - q[1],
                    shrink ? "shrinking" : "NOT SHRINKING");
        ok = ok && shrink;
      }

    std::printf("%s\n", ok ? "all checks passed" : "CHECK FAILED");
    return ok ? 0 : 1;
  }
} // namespace fgimpact_unit_tests::plastic_impact
