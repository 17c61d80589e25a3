#ifndef fgimpact_thermal_h
#define fgimpact_thermal_h

#include <deal.II/base/parameter_handler.h>

#include <fgimpact/base/selection.h>
#include <fgimpact/material/material.h>

#include <vector>

namespace fgimpact
{
  using namespace dealii;

  /// Thermal/Temperature field: how T varies through the thickness.
  enum class TemperatureField
  {
    /// No thermal environment: the plate is stress free at every
    /// temperature (the program as before).
    none,
    /// T = T_ref + Delta T everywhere.
    uniform,
    /// T linear in z from T_bottom (z = 0) to T_top (z = h).
    linear,
    /// Steady 1D conduction through the graded k(z): T_bottom at z = 0,
    /// T_top at z = h.
    conduction
  };

  /// The names of Thermal/Temperature field.
  const SelectionTable<TemperatureField> &
  temperature_field_names();

  /**
   * The subsection Thermal: the temperature field through the thickness
   * and the stress-free (reference) temperature.  Temperatures in K.
   */
  struct ThermalParameters
  {
    TemperatureField field                 = TemperatureField::none;
    double           reference_temperature = 300.;
    double           temperature_change    = 0.;
    double           top_temperature       = 300.;
    double           bottom_temperature    = 300.;
    /// Thermal/Geometric stiffness: the pre-stress's initial-stress
    /// stiffness joins K, and the thermal buckling factor is solved for.
    bool geometric_stiffness = false;

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);

    /// T (K) at the top (metal) and bottom (ceramic) faces: the field's
    /// boundary values (T_ref without a field).
    double
    face_temperature(const bool top) const
    {
      switch (field)
        {
          case TemperatureField::none:
            return reference_temperature;
          case TemperatureField::uniform:
            return reference_temperature + temperature_change;
          default:
            return top ? top_temperature : bottom_temperature;
        }
    }

    /// Whether a thermal step runs (Temperature field != none).
    bool
    active() const
    {
      return field != TemperatureField::none;
    }
  };

  /**
   * T(z) through the thickness h (m), z from the bottom face (ceramic).
   * For conduction, -(k T')' = 0 with T(0) = T_b, T(h) = T_t:
   *
   *   T(z) = T_b + (T_t - T_b) R(z) / R(h),  R(z) = int_0^z dz' / k(z'),
   *
   * R by 8-point Gauss-Legendre on 400 intervals clustered at both faces
   * (Chebyshev points, the end intervals split geometrically), where a
   * power law or a sigmoid with n < 1 has an unbounded slope
   * (doc/thermal.md).
   */
  class TemperatureProfile
  {
  public:
    TemperatureProfile(const ThermalParameters          &parameters,
                       const FunctionallyGradedMaterial &material);

    /// T(z) in K.
    double
    temperature(const double z) const;

    /// T(z) - T_ref in K: the change that strains the plate.
    double
    change(const double z) const
    {
      return temperature(z) - parameters.reference_temperature;
    }

    /// The thermal strain alpha(z) (T(z) - T_ref) (dimensionless), the
    /// same in every direction.
    double
    thermal_strain(const double z) const
    {
      const double T = temperature(z);
      return material.thermal_expansion(z, T) *
             (T - parameters.reference_temperature);
    }

    /// alpha(z) at T(z) (1/K).
    double
    thermal_expansion(const double z) const
    {
      return material.thermal_expansion(z, temperature(z));
    }

    /// Conduction with a temperature-dependent k: the fixed-point
    /// iterations it took (1 for a constant k, 0 for the other fields).
    unsigned int
    n_iterations() const
    {
      return iterations;
    }

    const ThermalParameters &
    get_parameters() const
    {
      return parameters;
    }

  private:
    /// R(z) = int_0^z dz'/k (m^2 K/W): the table's nodes, then one Gauss
    /// rule on the rest of the interval that holds z.
    double
    resistance(const double z) const;

    /// int_{z0}^{z1} dz'/k by 8-point Gauss-Legendre, k at the last
    /// iterate's temperature.
    double
    gauss_resistance(const double z0, const double z1) const;

    /// The last iterate's temperature at z: cubic Hermite between the
    /// nodes, with their exact slopes (error ~ dz^4 T'''').
    double
    iterate_temperature(const double z) const;

    /// Conduction: T at the nodes, by fixed-point iterations where k
    /// depends on T.
    void
    solve_conduction();

    /// R at the nodes with k at the last iterate's temperature.
    void
    integrate_resistances();

    const ThermalParameters           parameters;
    const FunctionallyGradedMaterial &material;
    const double                      h;
    /// Conduction: the interval ends, R and the last iterate's T and
    /// dT/dz at each (the flux is constant: dT/dz = (T_t - T_b) / (R(h)
    /// k)).
    std::vector<double> nodes, resistances, node_temperatures, node_slopes;
    unsigned int        iterations = 0;
  };
} // namespace fgimpact

#endif
