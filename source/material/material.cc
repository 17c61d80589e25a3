#include <fgimpact/base/parameter_table.h>
#include <fgimpact/material/material.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace fgimpact
{
  const SelectionTable<PropertyMode> &
  property_mode_names()
  {
    static const SelectionTable<PropertyMode> names = {
      {"graded", PropertyMode::graded},
      {"homogeneous", PropertyMode::homogeneous},
      {"pointwise", PropertyMode::pointwise}};
    return names;
  }



  const SelectionTable<GradedNodalValues> &
  graded_nodal_values_names()
  {
    static const SelectionTable<GradedNodalValues> names = {
      {"sampled", GradedNodalValues::sampled},
      {"layer average", GradedNodalValues::layer_average}};
    return names;
  }



  namespace
  {
    /// Material/Ceramic Poisson's ratio: 'same' (-2) or a number.
    void
    parse_ceramic_poissons_ratio(ParameterHandler                       &prm,
                                 FunctionallyGradedMaterial::Parameters &p)
    {
      const std::string nu_c = prm.get("Ceramic Poisson's ratio");
      if (nu_c == "same")
        p.ceramic_poissons_ratio = -2.;
      else
        {
          std::size_t end   = 0;
          double      value = 0;
          try
            {
              value = std::stod(nu_c, &end);
            }
          catch (...)
            {
              end = 0;
            }
          AssertThrow(end > 0 && end == nu_c.size() && value >= -0.99 &&
                        value <= 0.49,
                      ExcMessage("Material/Ceramic Poisson's ratio = '" + nu_c +
                                 "' is neither 'same' nor a number in "
                                 "[-0.99, 0.49]."));
          p.ceramic_poissons_ratio = value;
        }
    }
  } // namespace



  namespace
  {
    /// The constituents' moduli, densities and Poisson's ratio, and the
    /// power-law index.
    void
    add_constituent_rows(
      ParameterTable<FunctionallyGradedMaterial::Parameters> &t)
    {
      using P = FunctionallyGradedMaterial::Parameters;

      t.add("Metal Young's modulus",
            &P::metal_youngs_modulus,
            Patterns::Double(1e3, 1e15),
            "Young's modulus E_m of the metal constituent, on top "
            "of the plate (z = h). Unit: Pa.");
      t.add("Metal density",
            &P::metal_density,
            Patterns::Double(1e-3, 1e6),
            "Mass density rho_m of the metal constituent. "
            "Unit: kg/m^3.");
      t.add("Ceramic Young's modulus",
            &P::ceramic_youngs_modulus,
            Patterns::Double(1e3, 1e15),
            "Young's modulus E_c of the ceramic constituent, at "
            "the bottom of the plate (z = 0). Unit: Pa.");
      t.add("Ceramic density",
            &P::ceramic_density,
            Patterns::Double(1e-3, 1e6),
            "Mass density rho_c of the ceramic constituent. "
            "Unit: kg/m^3.");
      t.add("Poisson's ratio",
            &P::poissons_ratio,
            Patterns::Double(-0.99, 0.49),
            "Poisson's ratio nu of the metal, and of the "
            "ceramic unless Ceramic Poisson's ratio is set: then "
            "constant through the thickness (Eq. 2.12). "
            "Dimensionless.");
      t.add("Power-law index",
            &P::power_law_index,
            Patterns::Double(0., 1e6),
            "Volume fraction index n of Eq. 2.1, "
            "P(z) = P_c + (P_m - P_c) (z/h)^n with z from the "
            "bottom face. n = 0 is pure METAL (the paper's "
            "convention, opposite to most FGM papers); n -> "
            "infinity tends to pure ceramic. Dimensionless.");
    }

    /// The constituents' thermal expansion and conductivity.
    void
    add_thermal_rows(ParameterTable<FunctionallyGradedMaterial::Parameters> &t)
    {
      using P = FunctionallyGradedMaterial::Parameters;
      t.add("Metal thermal expansion",
            &P::metal_thermal_expansion,
            Patterns::Double(0., 1e-3),
            "Linear thermal expansion coefficient alpha_m of the metal "
            "constituent (read only with a Thermal/Temperature field); "
            "graded by the rule of mixtures at the metal volume fraction. "
            "Unit: 1/K.");
      t.add("Ceramic thermal expansion",
            &P::ceramic_thermal_expansion,
            Patterns::Double(0., 1e-3),
            "Linear thermal expansion coefficient alpha_c of the ceramic "
            "constituent. Unit: 1/K.");
      t.add("Metal conductivity",
            &P::metal_conductivity,
            Patterns::Double(1e-3, 1e5),
            "Thermal conductivity k_m of the metal constituent (read only "
            "with Thermal/Temperature field = conduction); graded by the "
            "rule of mixtures. Unit: W/(m K).");
      t.add("Ceramic conductivity",
            &P::ceramic_conductivity,
            Patterns::Double(1e-3, 1e5),
            "Thermal conductivity k_c of the ceramic constituent. "
            "Unit: W/(m K).");
    }

    /// The named, temperature-dependent constituents.
    void
    add_named_rows(ParameterTable<FunctionallyGradedMaterial::Parameters> &t)
    {
      using P = FunctionallyGradedMaterial::Parameters;
      t.add("Metal material",
            &P::metal_material,
            metal_material_names(),
            "The metal constituent (top face). constant: the Metal entries "
            "above. A name: its E, nu, rho, thermal expansion and "
            "conductivity follow the temperature field (Thermal), the "
            "graded property at a point being the mixture of the "
            "constituents at the local temperature; the Metal entries are "
            "then ignored (without a field: at Thermal/Reference "
            "temperature). Power-law and sigmoid gradations only. " +
              named_material_help());
      t.add("Ceramic material",
            &P::ceramic_material,
            ceramic_material_names(),
            "The ceramic constituent (bottom face): constant (the Ceramic "
            "entries above) or a name, as Metal material.");
    }

    /// How the properties are graded and interpolated.
    void
    add_grading_rows(ParameterTable<FunctionallyGradedMaterial::Parameters> &t)
    {
      using P = FunctionallyGradedMaterial::Parameters;
      t.add(
        "Property mode",
        &P::property_mode,
        property_mode_names(),
        "graded: E and rho are interpolated from their nodal values with the "
        "element shape functions at every quadrature point (graded finite "
        "elements, Eq. 3.3). homogeneous: one value per element, evaluated "
        "at the element centre (conventional elements). pointwise: E(z) and "
        "rho(z) of Eq. 2.1 evaluated at every quadrature point (no "
        "interpolation; for steep gradients, large n, where the graded "
        "interpolant smears the metal skin over the top element).");
      t.add("Gradation",
            &P::gradation,
            gradation_names(),
            "How the properties vary with zeta = z/h (z from the bottom face; "
            "metal on top). " +
              gradation_help());
      t.add(
        "Homogenization",
        &P::homogenization,
        homogenization_names(),
        "How E and nu of the mixture follow from the metal volume fraction "
        "(power law and sigmoid only). rule of mixtures: P = P_c + (P_m - "
        "P_c) V_m for E, nu and rho. Mori-Tanaka: metal matrix with ceramic "
        "inclusions, Mori-Tanaka bulk and shear moduli (nu then varies even "
        "with equal constituent ratios); rho by the rule of mixtures.");
      t.add(
        "Profile file",
        &P::profile_file,
        Patterns::FileName(),
        "Gradation = tabulated: a CSV file with the columns z/h (from the "
        "bottom face, strictly increasing from 0 to 1), E (Pa), nu and rho "
        "(kg/m^3); '#' starts a comment, one header line is allowed. A "
        "relative path is relative to the directory of the .prm given on "
        "the command line (parameters.prm records it as an absolute path).");
      t.add(
        "Graded nodal values",
        &P::graded_nodal_values,
        graded_nodal_values_names(),
        "Property mode = graded: the nodal values the elements interpolate. "
        "sampled: the profile at the nodes (Eq. 3.3). layer average: the "
        "element-wise L2 projection of the profile onto polynomials in z "
        "of the element degree, so that each element keeps the exact "
        "average of E, nu and rho over its thickness; a boundary layer "
        "thinner than an element (n -> 0+) is then not misread "
        "(doc/theory.md).");
    }

    /// The entries of Material that set a member as they stand.
    const ParameterTable<FunctionallyGradedMaterial::Parameters> &
    material_table()
    {
      using P = FunctionallyGradedMaterial::Parameters;
      static const ParameterTable<P> table = [] {
        ParameterTable<P> t;
        add_constituent_rows(t);
        add_thermal_rows(t);
        add_named_rows(t);
        add_grading_rows(t);
        return t;
      }();
      return table;
    }
  } // namespace



  void
  FunctionallyGradedMaterial::Parameters::declare_parameters(
    ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    {
      material_table().declare(prm);
      // Not a member as it stands: 'same' is ceramic_poissons_ratio < -1.
      const Parameters defaults;
      prm.declare_entry(
        "Ceramic Poisson's ratio",
        defaults.ceramic_poissons_ratio < -1. ?
          std::string("same") :
          prm_string(defaults.ceramic_poissons_ratio),
        Patterns::Anything(),
        "Poisson's ratio nu_c of the ceramic (bottom face): 'same' (the "
        "metal's, Poisson's ratio) or a number in [-0.99, 0.49]. With a "
        "different value nu varies through the thickness. Dimensionless.");
    }
    prm.leave_subsection();
  }



  void
  FunctionallyGradedMaterial::Parameters::parse_parameters(
    ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    {
      material_table().parse(prm, *this);
      parse_ceramic_poissons_ratio(prm, *this);
      AssertThrow(!temperature_dependent() ||
                    gradation == Gradation::power_law ||
                    gradation == Gradation::sigmoid,
                  ExcMessage("Material/Metal material or Ceramic material "
                             "names a constituent, which needs a gradation "
                             "of the two phases' volume fraction "
                             "(Material/Gradation = power law or sigmoid)."));
      AssertThrow(gradation != Gradation::tabulated || !profile_file.empty(),
                  ExcMessage("Material/Gradation = tabulated needs "
                             "Material/Profile file."));
    }
    prm.leave_subsection();
  }



  void
  FunctionallyGradedMaterial::Parameters::resolve_relative_paths(
    ParameterHandler  &prm,
    const std::string &prm_file)
  {
    // Made absolute in prm itself, so that parameters.prm, the checkpoints
    // (fgimpact --resume DIR reads DIR/parameters.prm) and a study's cases
    // name the same file wherever they are read from.
    namespace fs = std::filesystem;
    prm.enter_subsection("Material");
    const std::string file = prm.get("Profile file");
    if (!file.empty() && fs::path(file).is_relative())
      {
        const bool     named = !(prm_file.empty() || prm_file == "-" ||
                             prm_file == "standard input");
        const fs::path directory =
          named ? fs::path(prm_file).parent_path() : fs::path();
        prm.set("Profile file",
                fs::absolute(directory / file).lexically_normal().string());
      }
    prm.leave_subsection();
  }



  Constituents
  FunctionallyGradedMaterial::Parameters::constituents() const
  {
    return {{metal_youngs_modulus, poissons_ratio, metal_density},
            {ceramic_youngs_modulus,
             ceramic_poissons_ratio < -1. ? poissons_ratio :
                                            ceramic_poissons_ratio,
             ceramic_density}};
  }



  FunctionallyGradedMaterial::FunctionallyGradedMaterial(
    const Parameters                    &parameters,
    const double                         thickness,
    const std::function<double(double)> &temperature)
    : parameters(parameters)
    , h(thickness)
    , law(create_gradation_law(parameters.gradation,
                               parameters.homogenization,
                               parameters.constituents(),
                               parameters.power_law_index,
                               parameters.profile_file))
    , temperature(temperature)
  {}



  IsotropicProperties
  FunctionallyGradedMaterial::properties(const double z) const
  {
    const double zeta = std::clamp(z / h, 0., 1.);
    if (!follows_temperature())
      return law->properties(zeta);
    // The mixture of the constituents at the local temperature.
    return homogenize(constituents_at(temperature(z)),
                      law->metal_fraction(zeta),
                      parameters.homogenization);
  }



  double
  FunctionallyGradedMaterial::youngs_modulus(const double z) const
  {
    return properties(z).E;
  }



  double
  FunctionallyGradedMaterial::density(const double z) const
  {
    return properties(z).rho;
  }



  double
  FunctionallyGradedMaterial::poissons_ratio(const double z) const
  {
    // With equal constituent ratios every law returns nu_c + 0 * (...):
    // exactly the constant.
    return properties(z).nu;
  }



  bool
  FunctionallyGradedMaterial::constant_poissons_ratio() const
  {
    // Named constituents' nu follows T(z).
    return law->constant_poissons_ratio() && !follows_temperature();
  }



  double
  FunctionallyGradedMaterial::metal_volume_fraction(const double z) const
  {
    const double zeta = std::clamp(z / h, 0., 1.);
    const double Vm   = law->metal_fraction(zeta);
    if (std::isfinite(Vm))
      return Vm;
    const double Em = parameters.metal_youngs_modulus,
                 Ec = parameters.ceramic_youngs_modulus;
    if (Em == Ec)
      return 1.;
    return std::clamp((law->properties(zeta).E - Ec) / (Em - Ec), 0., 1.);
  }



  double
  FunctionallyGradedMaterial::thermal_expansion(const double z) const
  {
    if (follows_temperature())
      return thermal_expansion(z, temperature(z));
    const double Vm = metal_volume_fraction(z);
    return parameters.ceramic_thermal_expansion +
           (parameters.metal_thermal_expansion -
            parameters.ceramic_thermal_expansion) *
             Vm;
  }



  double
  FunctionallyGradedMaterial::conductivity(const double z) const
  {
    if (follows_temperature())
      return conductivity(z, temperature(z));
    const double Vm = metal_volume_fraction(z);
    return parameters.ceramic_conductivity +
           (parameters.metal_conductivity - parameters.ceramic_conductivity) *
             Vm;
  }



  double
  FunctionallyGradedMaterial::total_metal_volume_fraction() const
  {
    return law->total_metal_volume_fraction();
  }

} // namespace fgimpact
