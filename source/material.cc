#include <fgimpact/material.h>

#include <algorithm>
#include <cmath>

namespace fgimpact
{
  void
  FunctionallyGradedMaterial::Parameters::declare_parameters(
    ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    {
      prm.declare_entry("Metal Young's modulus",
                        "70e9",
                        Patterns::Double(1e3, 1e15),
                        "Young's modulus E_m of the metal constituent, on top "
                        "of the plate (z = h). Unit: Pa.");
      prm.declare_entry("Metal density",
                        "2707",
                        Patterns::Double(1e-3, 1e6),
                        "Mass density rho_m of the metal constituent. "
                        "Unit: kg/m^3.");
      prm.declare_entry("Ceramic Young's modulus",
                        "380e9",
                        Patterns::Double(1e3, 1e15),
                        "Young's modulus E_c of the ceramic constituent, at "
                        "the bottom of the plate (z = 0). Unit: Pa.");
      prm.declare_entry("Ceramic density",
                        "3800",
                        Patterns::Double(1e-3, 1e6),
                        "Mass density rho_c of the ceramic constituent. "
                        "Unit: kg/m^3.");
      prm.declare_entry("Poisson's ratio",
                        "0.3",
                        Patterns::Double(-0.99, 0.49),
                        "Poisson's ratio nu, the same for both constituents "
                        "and constant through the thickness (Eq. 2.12). "
                        "Dimensionless.");
      prm.declare_entry("Power-law index",
                        "1",
                        Patterns::Double(0., 1e6),
                        "Volume fraction index n of Eq. 2.1, "
                        "P(z) = P_c + (P_m - P_c) (z/h)^n with z from the "
                        "bottom face. n = 0 is pure METAL (the paper's "
                        "convention, opposite to most FGM papers); n -> "
                        "infinity tends to pure ceramic. Dimensionless.");
      prm.declare_entry(
        "Property mode",
        "graded",
        Patterns::Selection("graded|homogeneous|pointwise"),
        "graded: E and rho are interpolated from their nodal values with the "
        "element shape functions at every quadrature point (graded finite "
        "elements, Eq. 3.3). homogeneous: one value per element, evaluated "
        "at the element centre (conventional elements). pointwise: E(z) and "
        "rho(z) of Eq. 2.1 evaluated at every quadrature point (no "
        "interpolation; for steep gradients, large n, where the graded "
        "interpolant smears the metal skin over the top element).");
    }
    prm.leave_subsection();
  }



  void
  FunctionallyGradedMaterial::Parameters::parse_parameters(
    ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    {
      metal_youngs_modulus   = prm.get_double("Metal Young's modulus");
      metal_density          = prm.get_double("Metal density");
      ceramic_youngs_modulus = prm.get_double("Ceramic Young's modulus");
      ceramic_density        = prm.get_double("Ceramic density");
      poissons_ratio         = prm.get_double("Poisson's ratio");
      power_law_index        = prm.get_double("Power-law index");
      const std::string mode = prm.get("Property mode");
      property_mode          = (mode == "graded"      ? PropertyMode::graded :
                                mode == "homogeneous" ? PropertyMode::homogeneous :
                                                        PropertyMode::pointwise);
    }
    prm.leave_subsection();
  }



  FunctionallyGradedMaterial::FunctionallyGradedMaterial(
    const Parameters &parameters,
    const double      thickness)
    : parameters(parameters)
    , h(thickness)
  {}



  double
  FunctionallyGradedMaterial::metal_volume_fraction(const double z) const
  {
    const double zeta = std::clamp(z / h, 0., 1.);
    // pow(0, 0) is 1 in C++: n = 0 gives pure metal everywhere, including the
    // bottom face, as Eq. 2.1 requires.
    return std::pow(zeta, parameters.power_law_index);
  }



  double
  FunctionallyGradedMaterial::youngs_modulus(const double z) const
  {
    return parameters.ceramic_youngs_modulus +
           (parameters.metal_youngs_modulus -
            parameters.ceramic_youngs_modulus) *
             metal_volume_fraction(z);
  }



  double
  FunctionallyGradedMaterial::density(const double z) const
  {
    return parameters.ceramic_density +
           (parameters.metal_density - parameters.ceramic_density) *
             metal_volume_fraction(z);
  }



  double
  FunctionallyGradedMaterial::lambda_per_E() const
  {
    const double nu = parameters.poissons_ratio;
    return nu / ((1. + nu) * (1. - 2. * nu));
  }



  double
  FunctionallyGradedMaterial::mu_per_E() const
  {
    return 1. / (2. * (1. + parameters.poissons_ratio));
  }



  double
  FunctionallyGradedMaterial::total_metal_volume_fraction() const
  {
    return 1. / (1. + parameters.power_law_index);
  }



  double
  FunctionallyGradedMaterial::mass_per_unit_area() const
  {
    const double Vm = total_metal_volume_fraction();
    return h * (parameters.ceramic_density * (1. - Vm) +
                parameters.metal_density * Vm);
  }
} // namespace fgimpact
