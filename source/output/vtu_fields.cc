// The VTU's fields: which ones a run writes (VtuFields, Output/VTU fields)
// and the stress postprocessor that computes them per cell (the writer is in
// postprocessing.cc).

#include <deal.II/base/exceptions.h>
#include <deal.II/base/symmetric_tensor.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/numerics/data_out.h>

#include <fgimpact/base/checkpoint.h>
#include <fgimpact/base/exceptions.h>
#include <fgimpact/base/files.h>
#include <fgimpact/base/parameter_table.h>
#include <fgimpact/output/mirrored_data_out.h>
#include <fgimpact/output/output_files.h>
#include <fgimpact/output/postprocessing.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <sstream>

namespace fgimpact
{
  StressPostprocessor::StressPostprocessor(const PlateModel &plate,
                                           const bool        with_stress,
                                           const bool        with_material)
    : plate(plate)
    , mapping(plate.get_mapping())
    , properties(plate.get_fe().base_element(0), {}, plate.get_material())
    , hooke(plate.get_material())
    , with_stress(with_stress)
    , with_material(with_material)
  {}



  std::vector<std::string>
  StressPostprocessor::get_names() const
  {
    std::vector<std::string> names;
    if (with_stress)
      {
        names.resize(9, "stress_MPa");
        names.emplace_back("cell_von_mises_MPa");
      }
    if (with_material)
      {
        names.emplace_back("youngs_modulus_GPa");
        names.emplace_back("density_kg_m3");
      }
    return names;
  }



  std::vector<DataComponentInterpretation::DataComponentInterpretation>
  StressPostprocessor::get_data_component_interpretation() const
  {
    std::vector<DataComponentInterpretation::DataComponentInterpretation>
      interpretation;
    if (with_stress)
      interpretation.resize(
        9, DataComponentInterpretation::component_is_part_of_tensor);
    interpretation.resize(get_names().size(),
                          DataComponentInterpretation::component_is_scalar);
    return interpretation;
  }



  UpdateFlags
  StressPostprocessor::get_needed_update_flags() const
  {
    return update_gradients | update_quadrature_points;
  }



  void
  StressPostprocessor::evaluate_vector_field(
    const DataPostprocessorInputs::Vector<3> &inputs,
    std::vector<Vector<double>>              &computed_quantities) const
  {
    const auto cell = inputs.template get_cell<3>();
    // B-bar: the cell's mean dilatation replaces the pointwise one.
    const bool   bbar  = with_stress && plate.uses_mean_dilatation();
    const double theta = bbar ? plate.mean_dilatation(cell, *displacement) : 0.;
    const std::vector<SymmetricTensor<2, 3>> eps0 =
      with_stress && initial ? initial_strain(cell, inputs.evaluation_points) :
                               std::vector<SymmetricTensor<2, 3>>();
    const std::vector<SymmetricTensor<2, 3>> eps_modes =
      mode_strains(cell, inputs.evaluation_points);
    for (unsigned int p = 0; p < inputs.solution_gradients.size(); ++p)
      {
        const auto [E, nu, rho] =
          properties.value_at(cell, inputs.evaluation_points[p]);
        unsigned int k = 0;
        if (with_stress)
          {
            SymmetricTensor<2, 3> eps;
            for (unsigned int a = 0; a < 3; ++a)
              for (unsigned int b = a; b < 3; ++b)
                eps[a][b] = 0.5 * (inputs.solution_gradients[p][a][b] +
                                   inputs.solution_gradients[p][b][a]);
            if (bbar)
              eps = PlateModel::with_dilatation(eps, theta);
            eps += eps_modes[p];
            if (initial)
              eps += eps0[p]; // the total stress
            SymmetricTensor<2, 3> sigma = hooke.stress(E, nu, eps);
            if (plastic)
              {
                // The stress the material carries: C (eps - eps_p), on
                // or inside the yield surface (as StressRecovery).
                const PlasticState state =
                  plastic->plastic_state(cell->active_cell_index(),
                                         mapping.transform_real_to_unit_cell(
                                           cell, inputs.evaluation_points[p]));
                sigma = J2Plasticity::admissible_stress(
                  hooke.stress(E, nu, eps - state.plastic_strain),
                  plastic->yield_stress(inputs.evaluation_points[p][2],
                                        state.equivalent_plastic_strain));
              }
            const SymmetricTensor<2, 3> s = deviator(sigma);

            for (unsigned int a = 0; a < 3; ++a)
              for (unsigned int b = 0; b < 3; ++b)
                computed_quantities[p][k++] = sigma[a][b] * 1e-6;
            computed_quantities[p][k++] = std::sqrt(1.5 * (s * s)) * 1e-6;
          }
        if (with_material)
          {
            computed_quantities[p][k++] = E * 1e-9;
            computed_quantities[p][k++] = rho;
          }
      }
  }



  std::vector<SymmetricTensor<2, 3>>
  StressPostprocessor::mode_strains(
    const DoFHandler<3>::active_cell_iterator &cell,
    const std::vector<Point<3>>               &points) const
  {
    std::vector<SymmetricTensor<2, 3>> eps(points.size());
    if (with_stress && plate.uses_incompatible_modes())
      {
        std::vector<Point<3>> unit_points;
        for (const auto &p : points)
          unit_points.push_back(mapping.transform_real_to_unit_cell(cell, p));
        plate.add_mode_strains(cell, unit_points, *displacement, eps);
      }
    return eps;
  }



  std::vector<SymmetricTensor<2, 3>>
  StressPostprocessor::initial_strain(
    const DoFHandler<3>::active_cell_iterator &cell,
    const std::vector<Point<3>>               &points) const
  {
    std::vector<Point<3>> unit_points;
    for (const auto &x : points)
      unit_points.push_back(mapping.transform_real_to_unit_cell(cell, x));
    FEValues<3> fe_values(mapping,
                          plate.get_fe(),
                          Quadrature<3>(unit_points),
                          update_gradients | update_quadrature_points);
    fe_values.reinit(cell);
    std::vector<SymmetricTensor<2, 3>> eps0;
    initial->strain(fe_values, cell, eps0);
    return eps0;
  }



  namespace
  {
    /// Output/Fields: each name and its flag, in the pattern's order.
    const std::array<std::pair<std::string, bool VtuFields::*>, 11>
      field_flags = {{{"displacement", &VtuFields::displacement},
                      {"velocity", &VtuFields::velocity},
                      {"acceleration", &VtuFields::acceleration},
                      {"stress", &VtuFields::stress},
                      {"von_mises", &VtuFields::von_mises},
                      {"principal", &VtuFields::principal},
                      {"strain", &VtuFields::strain},
                      {"cell_stress", &VtuFields::cell_stress},
                      {"material", &VtuFields::material},
                      {"peak", &VtuFields::peak},
                      {"thermal", &VtuFields::thermal}}};

    /// "a|b|..." (all = false: the pattern) or "a, b, ..." of the flags
    /// set in `fields` (the default).
    std::string
    field_list(const VtuFields &fields, const bool all)
    {
      std::string list;
      for (const auto &[name, flag] : field_flags)
        if (all || fields.*flag)
          list += (list.empty() ? "" : (all ? "|" : ", ")) + name;
      return list;
    }

    /// The entries of VtuFields that set a member as they stand.
    const ParameterTable<VtuFields> &
    vtu_fields_table()
    {
      using P                              = VtuFields;
      static const ParameterTable<P> table = [] {
        ParameterTable<P> t;
        t.add(
          "Mirror symmetric part",
          &P::mirror,
          Patterns::Bool(),
          "With Geometry/Symmetry modelling a half or a quarter of the plate: "
          "true writes the VTU files of the whole plate (the part and its "
          "reflections across the cut planes x = a/2, y = b/2, with the signs of "
          "the odd vector and tensor components changed); false writes the "
          "modelled part only (mirror it in ParaView with the Reflect filter). "
          "No effect on a whole plate.");
        return t;
      }();
      return table;
    }
  } // namespace



  void
  VtuFields::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry(
      "Fields",
      field_list(VtuFields(), false),
      Patterns::MultipleSelection(field_list(VtuFields(), true)),
      "The fields of the VTU files, a comma-separated list of: "
      "displacement (displacement_m, m), velocity (velocity_m_s, m/s), "
      "acceleration (impact runs: acceleration_m_s2, m/s^2), "
      "stress (the recovered, continuous stress by nodal averaging: "
      "sigma_xx_MPa, sigma_yy_MPa, sigma_zz_MPa, sigma_xy_MPa, sigma_xz_MPa, "
      "sigma_yz_MPa, MPa), von_mises (recovered von_mises_MPa, MPa), "
      "principal (recovered principal stresses sigma_1_MPa >= sigma_2_MPa "
      ">= sigma_3_MPa, MPa), strain (recovered strain_xx ... strain_yz, "
      "tensor components, dimensionless), cell_stress (the per-cell, "
      "discontinuous stress tensor stress_MPa with components 0..8 = xx, "
      "xy, xz, yx, yy, yz, zx, zy, zz and cell_von_mises_MPa, MPa), "
      "material (youngs_modulus_GPa in GPa, density_kg_m3 in kg/m^3), peak "
      "(impact runs: peak_fields.vtu at the end, the nodal maxima over the "
      "VTU snapshots of the recovered von Mises stress and |sigma_zz|, "
      "MPa), thermal (with a Thermal/Temperature field: the thermal step's "
      "displacement thermal_displacement_m in m, the temperature "
      "temperature_K in K, the expansion coefficient thermal_expansion_per_K "
      "in 1/K and the thermal state's per-cell stress tensor "
      "thermal_stress_MPa in MPa; no effect without a field). With a "
      "temperature field every stress field is the total stress, the "
      "thermal state's plus the analysis's, while displacement, velocity, "
      "acceleration and strain are the analysis's, measured from the "
      "thermal state.");
    vtu_fields_table().declare(prm);
  }



  void
  VtuFields::parse_parameters(ParameterHandler &prm)
  {
    const auto list = Utilities::split_string_list(prm.get("Fields"));
    for (const auto &[name, flag] : field_flags)
      this->*flag = std::find(list.begin(), list.end(), name) != list.end();
    vtu_fields_table().parse(prm, *this);
  }
} // namespace fgimpact
