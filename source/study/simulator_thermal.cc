#include <fgimpact/analysis/thermal_step.h>
#include <fgimpact/study/simulator.h>

// The thermal environment's part of the Simulator (issue 42,
// doc/thermal.md): the material bound to T(z), the thermal step.

namespace fgimpact
{
  void
  Simulator::make_material()
  {
    material =
      std::make_unique<FunctionallyGradedMaterial>(parameters.material,
                                                   geometry->thickness());
    if (parameters.material.temperature_dependent())
      {
        // Named constituents follow T(z), whose conduction profile needs
        // their k(T): the profile from the unbound material, then the
        // plate's material bound to it.
        unbound_material = std::move(material);
        temperature_profile =
          std::make_unique<TemperatureProfile>(parameters.thermal,
                                               *unbound_material);
        const TemperatureProfile *T = temperature_profile.get();
        const double T_ref          = parameters.thermal.reference_temperature;
        const bool   field          = parameters.thermal.active();
        material = std::make_unique<FunctionallyGradedMaterial>(
          parameters.material,
          geometry->thickness(),
          [T, T_ref, field](const double z) {
            return field ? T->temperature(z) : T_ref;
          });
      }
  }



  void
  Simulator::run_thermal_step()
  {
    if (parameters.thermal.active())
      {
        thermal = std::make_unique<ThermalStep>(parameters.thermal,
                                                *plate,
                                                parameters.linear_solver);
        thermal->run();
        thermal->print(pcout, parameters.output.print_timing);
        if (parameters.thermal.geometric_stiffness)
          plate->add_initial_stress_stiffness(thermal->geometric_stiffness());
        summary_file.set_appendix(thermal->summary());
      }
  }
} // namespace fgimpact
