#include <deal.II/base/exceptions.h>

#include <fgimpact/base/parameter_table.h>
#include <fgimpact/problem/accuracy_preset.h>
#include <fgimpact/time/time_stepper.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace fgimpact
{
  const std::vector<AccuracyPreset::Setting> &
  AccuracyPreset::settings()
  {
    // From the speed/accuracy map of the default scene (doc/accuracy.md,
    // bench/accuracy_map.sh): the in-plane size stays at the default 5 mm,
    // the thickness mesh and the time step converge.
    static const std::vector<Setting> s = {{"fast", 5e-3, 2, 2e-6},
                                           {"standard", 5e-3, 4, 1e-6},
                                           {"accurate", 5e-3, 16, 1e-6}};
    return s;
  }



  unsigned int
  AccuracyPreset::even_subdivisions(const double length,
                                    const double element_size)
  {
    return 2 * std::max(1L, std::lround(length / (2. * element_size)));
  }



  const SelectionTable<AccuracyPreset::Preset> &
  AccuracyPreset::preset_names()
  {
    static const SelectionTable<Preset> names = {{"custom", Preset::custom},
                                                 {"fast", Preset::fast},
                                                 {"standard", Preset::standard},
                                                 {"accurate", Preset::accurate},
                                                 {"converged",
                                                  Preset::converged}};
    return names;
  }



  namespace
  {
    /// The entries of AccuracyPreset::Parameters that set a member as they
    /// stand.
    const ParameterTable<AccuracyPreset::Parameters> &
    accuracy_table()
    {
      using P                              = AccuracyPreset::Parameters;
      static const ParameterTable<P> table = [] {
        ParameterTable<P> t;
        t.add(
          "Accuracy",
          &P::preset,
          AccuracyPreset::preset_names(),
          "Discretization preset. custom: Geometry/Subdivisions x, y, z and "
          "Time integration/Time step as given. The others overwrite those "
          "four entries (the written parameters.prm shows the effective "
          "values) and keep the in-plane element size at 5 mm (Subdivisions x, "
          "y = the nearest even number of 5 mm elements): under the paper's "
          "point contact force the in-plane size under the ball sets the "
          "contact force, which does not converge under refinement (-8 to -9 "
          "% per halving), so the presets fix it and results are comparable "
          "only at equal in-plane size. Errors for the default scene "
          "(prm/default.prm, doc/accuracy.md) relative to the thickness- and "
          "dt-converged values at 5 mm, peak force / contact duration / "
          "departure velocity / max mid-plane deflection: fast = 2 elements "
          "through the thickness, dt = 2 us (40 x 20 x 2, 7749 DoFs, about "
          "1 s): +7.9 / -5.8 / -1.8 / -4.3 %. standard = 4 elements, dt = 1 "
          "us, the default mesh (12915 DoFs, about 3.5 s): +3.3 / -2.6 / -1.0 "
          "/ -0.3 %. accurate = 16 elements, dt = 1 us (43911 DoFs, about "
          "20 s): +0.31 / -0.26 / -0.10 / +0.04 %. Presets need Time "
          "integration/Scheme = implicit; the mesh applies to every Problem "
          "type. converged: an impact with Contact/Model = resolved sphere or "
          "hertz midplane run at increasing Geometry/Contact refinement levels "
          "(from one below the scene's automatic level), base meshes "
          "(Subdivisions doubled in plane and through the thickness) and "
          "contact levels on the final base, then once at half the Time step, "
          "refining further the source with the largest share until, for the "
          "peak contact force, contact duration, departure velocity, largest "
          "mid-plane deflection, indentation and the probes' peak stresses, "
          "the error estimates of the four sources add up to at most Accuracy "
          "tolerance; convergence.csv, and each number's estimate and its "
          "sources in summary.txt (doc/accuracy.md).");
        t.add("Accuracy tolerance",
              &P::tolerance,
              Patterns::Double(1e-6, 0.5),
              "Accuracy = converged: the bound on each headline "
              "number's relative error estimate, the sum of its "
              "contact levels', base mesh's (in plane, through the "
              "thickness) and time step's, each times a factor of "
              "safety of 1.25 (Roache's grid convergence index). "
              "Dimensionless (0.01 = 1 %).");
        return t;
      }();
      return table;
    }
  } // namespace



  void
  AccuracyPreset::Parameters::declare_parameters(ParameterHandler &prm)
  {
    accuracy_table().declare(prm);
  }



  void
  AccuracyPreset::Parameters::apply(ParameterHandler &prm)
  {
    accuracy_table().parse(prm, *this);
    file_subdivisions_x = file_subdivisions_y = file_subdivisions_z = 0;
    file_time_step                                                  = 0;
    if (preset == Preset::custom || preset == Preset::converged)
      return;
    const Setting &s =
      *std::find_if(settings().begin(),
                    settings().end(),
                    [&](const Setting &x) {
                      return x.name == preset_names().name(preset);
                    });

    prm.enter_subsection("Time integration");
    const bool explicit_scheme =
      (TimeStepper::scheme_names().value(prm.get("Scheme")) ==
       TimeStepper::Scheme::central_difference);
    const double old_dt = prm.get_double("Time step");
    prm.leave_subsection();
    AssertThrow(!explicit_scheme,
                ExcMessage("Accuracy = " + preset_names().name(preset) +
                           " sets the implicit scheme's time step; with "
                           "Time integration/Scheme = explicit use "
                           "Accuracy = custom."));

    prm.enter_subsection("Geometry");
    const unsigned int old_n[3] = {
      static_cast<unsigned int>(prm.get_integer("Subdivisions x")),
      static_cast<unsigned int>(prm.get_integer("Subdivisions y")),
      static_cast<unsigned int>(prm.get_integer("Subdivisions z"))};
    const unsigned int n[3] = {
      even_subdivisions(prm.get_double("Length a"), s.element_size),
      even_subdivisions(prm.get_double("Width b"), s.element_size),
      s.subdivisions_z};
    // The entries' bound (Patterns::Integer(1, 100000)).
    AssertThrow(n[0] <= 100000 && n[1] <= 100000,
                ExcMessage("Accuracy = " + preset_names().name(preset) +
                           ": Geometry/Length a or Width b needs more than "
                           "100000 elements of 5 mm; use Accuracy = "
                           "custom."));
    prm.set("Subdivisions x", static_cast<long int>(n[0]));
    prm.set("Subdivisions y", static_cast<long int>(n[1]));
    prm.set("Subdivisions z", static_cast<long int>(n[2]));
    prm.leave_subsection();

    char dt_text[40];
    std::snprintf(dt_text, sizeof(dt_text), "%g", s.time_step);
    prm.enter_subsection("Time integration");
    prm.set("Time step", std::string(dt_text));
    prm.leave_subsection();

    file_subdivisions_x = old_n[0];
    file_subdivisions_y = old_n[1];
    file_subdivisions_z = old_n[2];
    file_time_step      = old_dt;
  }



  std::string
  AccuracyPreset::Parameters::applied_message(const unsigned int nx,
                                              const unsigned int ny,
                                              const unsigned int nz) const
  {
    if (preset == Preset::custom || preset == Preset::converged)
      return "";
    const Setting &s =
      *std::find_if(settings().begin(),
                    settings().end(),
                    [&](const Setting &x) {
                      return x.name == preset_names().name(preset);
                    });
    char line[400];
    std::snprintf(line,
                  sizeof(line),
                  "Accuracy = %s sets Geometry/Subdivisions x, y, z = %u, "
                  "%u, %u (%g mm in plane) and Time integration/Time step "
                  "= %g us (the file had %u, %u, %u and %g us)",
                  preset_names().name(preset).c_str(),
                  nx,
                  ny,
                  nz,
                  s.element_size * 1e3,
                  s.time_step * 1e6,
                  file_subdivisions_x,
                  file_subdivisions_y,
                  file_subdivisions_z,
                  file_time_step * 1e6);
    return line;
  }
} // namespace fgimpact
