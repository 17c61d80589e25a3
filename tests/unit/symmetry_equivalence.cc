// Geometry/Symmetry: the quarter and half models of a doubly symmetric
// scene against the whole plate (an independent computation on 2 or 4
// times the mesh): every history.csv column and every physical summary
// entry equal to 1e-9 relative (relative to the column's largest value),
// for the Hertz node contact (implicit, and explicit at a given step, with
// local refinement),
// the Hertz mid-plane contact and the resolved sphere with two levels of
// local refinement; static point and sphere loads; and the one-line
// refusals naming what breaks the symmetry.  Each column's verdict is
// printed, not its largest difference: that is round-off, whose digits
// depend on the CPU and the BLAS kernel.

#include <deal.II/base/mpi.h>

#include <fgimpact/problem/symmetry.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <test_tools.h>

namespace fgimpact_unit_tests::symmetry_equivalence
{

  using namespace fgimpact;
  using fgimpact_tests::run_quietly;
  using fgimpact_tests::RunOutput;

  namespace
  {
    const std::string mesh =
      "subsection Geometry\n set Subdivisions x = 12\n set Subdivisions y = 6\n"
      " set Subdivisions z = 2\nend\n"
      "subsection Output\n set Directory = out\n set Log interval = 0\n"
      " set Print timing = false\nend\n";

    RunOutput
    run(const std::string &settings, const std::string &symmetry)
    {
      return run_quietly("",
                         mesh + settings +
                           "subsection Geometry\n set Symmetry = " + symmetry +
                           "\nend\n",
                         MPI_COMM_WORLD,
                         true);
    }

    /// max over rows |a - b| / max |a| of one column.
    double
    column_difference(const RunOutput &a, const RunOutput &b, unsigned int c)
    {
      double scale = 0, diff = 0;
      for (unsigned int r = 0; r < a.history.size(); ++r)
        {
          scale = std::max(scale, std::abs(a.history[r][c]));
          diff  = std::max(diff, std::abs(a.history[r][c] - b.history[r][c]));
        }
      return scale > 0 ? diff / scale : diff;
    }

    double
    relative(const double a, const double b)
    {
      if (std::isnan(a) && std::isnan(b))
        return 0;
      return a == b ? 0. : std::abs(a - b) / std::max(std::abs(a), std::abs(b));
    }

    /// The physical entries of summary.txt.
    double
    summary_difference(const ImpactResults &a, const ImpactResults &b)
    {
      const double d[] = {
        relative(a.peak_contact_force, b.peak_contact_force),
        relative(a.max_sampled_force, b.max_sampled_force),
        relative(a.time_of_peak_force, b.time_of_peak_force),
        relative(a.contact_duration, b.contact_duration),
        relative(a.departure_velocity, b.departure_velocity),
        relative(a.max_indentation, b.max_indentation),
        relative(a.max_approach, b.max_approach),
        relative(a.max_contact_radius, b.max_contact_radius),
        relative(a.max_contact_pressure, b.max_contact_pressure),
        relative(a.max_contact_nodes, b.max_contact_nodes),
        relative(a.max_midplane_deflection, b.max_midplane_deflection),
        relative(a.max_top_deflection, b.max_top_deflection),
        relative(a.contact_stiffness, b.contact_stiffness),
        relative(a.impactor_mass, b.impactor_mass),
        relative(a.plate_mass, b.plate_mass),
        relative(a.impulse, b.impulse),
        relative(a.n_contact_candidates, b.n_contact_candidates),
        // already relative to E0, and round-off small in some scenes
        std::abs(a.max_energy_drift - b.max_energy_drift),
        relative(a.n_impacts, b.n_impacts),
        relative(a.n_time_steps, b.n_time_steps),
        relative(a.max_newton_iterations, b.max_newton_iterations)};
      return *std::max_element(std::begin(d), std::end(d));
    }

    bool
    compare_scene(const std::string &name, const std::string &settings)
    {
      static const char *column_names[] = {"t_us",
                                           "contact_force_N",
                                           "indentation_um",
                                           "approach_um",
                                           "impactor_displacement_um",
                                           "impactor_velocity_m_s",
                                           "midplane_deflection_um",
                                           "top_deflection_um",
                                           "sigma_xx_mid_MPa",
                                           "sigma_yy_mid_MPa",
                                           "sigma_zz_mid_MPa",
                                           "energy_impactor_J",
                                           "energy_plate_kinetic_J",
                                           "energy_strain_J",
                                           "energy_contact_J",
                                           "energy_total_J",
                                           "contact_node_deflection_um",
                                           "newton_iterations",
                                           "contact_radius_mm",
                                           "max_contact_pressure_MPa",
                                           "n_contact_nodes"};
      const RunOutput    whole          = run(settings, "none");
      bool               ok             = true;
      std::printf("%s: %zu rows, peak force %.3f N\n",
                  name.c_str(),
                  whole.history.size(),
                  whole.results.peak_contact_force);
      for (const std::string part : {"half", "quarter"})
        {
          const RunOutput model = run(settings, part);
          bool            same = model.history.size() == whole.history.size() &&
                      model.history[0].size() == whole.history[0].size();
          double worst = 0;
          std::printf("  %s vs none, max relative difference per column:\n",
                      part.c_str());
          for (unsigned int c = 0; same && c < whole.history[0].size(); ++c)
            {
              const double d = column_difference(whole, model, c);
              worst          = std::max(worst, d);
              std::printf("    %-28s below 1e-9: %s\n",
                          column_names[c],
                          d < 1e-9 ? "yes" : "NO");
            }
          const double s = summary_difference(whole.results, model.results);
          std::printf("    %-28s below 1e-9: %s\n",
                      "summary (physical entries)",
                      s < 1e-9 ? "yes" : "NO");
          same = same && worst < 1e-9 && s < 1e-9;
          std::printf("  %s: history and summary equal to 1e-9: %s (%u vs %u "
                      "DoFs)\n",
                      part.c_str(),
                      same ? "yes" : "NO",
                      model.results.n_dofs,
                      whole.results.n_dofs);
          ok = ok && same;
        }
      return ok;
    }

    /// The first line of the error thrown while resolving `settings`.
    std::string
    refusal(const std::string &settings)
    {
      ParameterHandler prm;
      Parameters::declare_parameters(prm);
      prm.parse_input_from_string(mesh + settings);
      Parameters    p;
      SymmetricPart part;
      try
        {
          p.parse_parameters(prm);
          p.validate();
          part = resolve_symmetry(p);
        }
      catch (const ExceptionBase &e)
        {
          std::ostringstream s;
          e.print_info(s);
          std::string text = s.str();
          text.erase(0, text.find_first_not_of(" \n"));
          return text.substr(0, text.find('\n'));
        }
      return "not refused: cuts x " + std::to_string(part.cut[0]) + ", y " +
             std::to_string(part.cut[1]);
    }

    /// Entries of a summary.txt ("name = value" lines).
    std::map<std::string, double>
    read_summary(const std::string &file)
    {
      std::map<std::string, double> values;
      std::ifstream                 in(file);
      std::string                   line;
      while (std::getline(in, line))
        {
          const auto eq = line.find('=');
          if (eq == std::string::npos)
            continue;
          std::string key = line.substr(0, eq);
          key.erase(key.find_last_not_of(' ') + 1);
          try
            {
              values[key] = std::stod(line.substr(eq + 1));
            }
          catch (...)
            {}
        }
      return values;
    }

    bool
    compare_static(const std::string &name, const std::string &settings)
    {
      std::map<std::string, std::map<std::string, double>> summaries;
      for (const std::string part : {"none", "quarter"})
        {
          try
            {
              run(settings, part);
            }
          catch (const ExceptionBase &)
            {} // not an impact run: get_results() throws after the run
          summaries[part] = read_summary("out/summary.txt");
        }
      double worst = 0;
      for (const auto &[key, value] : summaries["none"])
        if (key.rfind("static_", 0) == 0)
          worst = std::max(worst, relative(value, summaries["quarter"][key]));
      const bool ok = worst < 1e-9 && summaries["none"].size() > 0;
      std::printf("%s: quarter vs none, %zu static entries, max relative "
                  "difference below 1e-9: %s\n",
                  name.c_str(),
                  summaries["none"].size(),
                  ok ? "yes" : "NO");
      return ok;
    }
  } // namespace

  int
  test_main(int argc, char **argv)
  {
    Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
    bool                             ok = true;
    ok =
      compare_scene("hertz node, implicit, 1 refinement level",
                    "subsection Geometry\n set Contact refinement levels = 1\n"
                    "end\nsubsection Time integration\n set Time step = 1e-6\n"
                    " set End time = 150e-6\nend\n") &&
      ok;
    ok =
      compare_scene("hertz node, explicit, dt = 0.25 us, 1 refinement level",
                    "subsection Geometry\n set Contact refinement levels = 1\n"
                    "end\nsubsection Time integration\n set Scheme = "
                    "explicit\n set Time step = 0.25e-6\n"
                    " set End time = 150e-6\nend\n") &&
      ok;
    ok = compare_scene("hertz midplane, implicit",
                       "subsection Contact\n set Model = hertz midplane\nend\n"
                       "subsection Time integration\n set Time step = 1e-6\n"
                       " set End time = 150e-6\nend\n") &&
         ok;
    ok = compare_scene(
           "resolved sphere, implicit, 2 refinement levels",
           "subsection Contact\n set Model = resolved sphere\nend\n"
           "subsection Geometry\n set Contact refinement levels = 2\nend\n"
           "subsection Time integration\n set Time step = 1e-6\n"
           " set End time = 60e-6\nend\n") &&
         ok;
    ok = compare_static("static point load",
                        "set Problem type = static\nsubsection Static\n"
                        " set Load = point\nend\n") &&
         ok;
    ok = compare_static("static sphere, 2 refinement levels",
                        "set Problem type = static\nsubsection Static\n"
                        " set Load = sphere\nend\n"
                        "subsection Geometry\n set Contact refinement levels = "
                        "2\nend\n") &&
         ok;

    std::printf("refusals and fall-backs:\n");
    const std::string cases[][2] = {
      {"subsection Geometry\n set Symmetry = quarter\nend\n"
       "subsection Impactor\n set Impact point x = 0.07\nend\n",
       "Impact point x"},
      {"subsection Geometry\n set Symmetry = quarter\nend\n"
       "subsection Boundary conditions\n set Face y max = clamped\nend\n",
       "Face y max"},
      {"subsection Geometry\n set Symmetry = half\n set Subdivisions x = 11\n"
       " set Subdivisions y = 7\nend\n",
       "Subdivisions y = 7"},
      {"subsection Geometry\n set Symmetry = quarter\nend\n"
       "subsection Time integration\n set Scheme = explicit\n"
       " set Time step = 0\nend\n",
       "Scheme = explicit with Time step = 0"},
      {"set Problem type = modal\nsubsection Geometry\n set Symmetry = "
       "quarter\nend\n",
       "modal"},
      {"subsection Geometry\n set Symmetry = auto\n set Subdivisions x = 11\nend\n",
       "cuts x 0, y 1"},
      {"subsection Geometry\n set Symmetry = auto\nend\n", "cuts x 1, y 1"}};
    for (const auto &c : cases)
      {
        const std::string text = refusal(c[0]);
        const bool        hit  = text.find(c[1]) != std::string::npos;
        std::printf("  %s: %s\n", hit ? "yes" : "NO", text.c_str());
        ok = ok && hit;
      }
    std::printf("%s\n", ok ? "all checks passed" : "SOME CHECKS FAILED");
    return ok ? 0 : 1;
  }
} // namespace fgimpact_unit_tests::symmetry_equivalence
