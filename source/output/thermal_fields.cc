// A thermal run's VTU (issue 42): the total stress in every stress field
// (VtuWriter::set_prestress()) and the thermal step's own fields
// (ThermalPostprocessor, Output/Fields = thermal).

#include <deal.II/base/symmetric_tensor.h>

#include <fgimpact/output/postprocessing.h>

namespace fgimpact
{
  ThermalPostprocessor::ThermalPostprocessor(const PlateModel    &plate,
                                             const InitialStress &initial)
    : plate(plate)
    , initial(initial)
    , properties(plate.get_fe().base_element(0), {}, plate.get_material())
  {}



  std::vector<std::string>
  ThermalPostprocessor::get_names() const
  {
    std::vector<std::string> names = {"temperature_K",
                                      "thermal_expansion_per_K"};
    names.resize(2 + 9, "thermal_stress_MPa");
    return names;
  }



  std::vector<DataComponentInterpretation::DataComponentInterpretation>
  ThermalPostprocessor::get_data_component_interpretation() const
  {
    std::vector<DataComponentInterpretation::DataComponentInterpretation>
      interpretation(2, DataComponentInterpretation::component_is_scalar);
    interpretation.resize(
      2 + 9, DataComponentInterpretation::component_is_part_of_tensor);
    return interpretation;
  }



  UpdateFlags
  ThermalPostprocessor::get_needed_update_flags() const
  {
    return update_gradients | update_quadrature_points;
  }



  void
  ThermalPostprocessor::evaluate_vector_field(
    const DataPostprocessorInputs::Vector<3> &inputs,
    std::vector<Vector<double>>              &computed_quantities) const
  {
    const auto cell = inputs.template get_cell<3>();
    // Attached to u0: its gradients, with B-bar the cell's mean dilatation.
    const bool   bbar = plate.uses_mean_dilatation();
    const double theta =
      bbar ? plate.mean_dilatation(cell, initial.displacement()) : 0.;
    const TemperatureProfile &profile = initial.temperature();
    for (unsigned int p = 0; p < inputs.solution_gradients.size(); ++p)
      {
        const double z = inputs.evaluation_points[p][2];
        const auto [E, nu, rho] =
          properties.value_at(cell, inputs.evaluation_points[p]);
        SymmetricTensor<2, 3> eps;
        for (unsigned int a = 0; a < 3; ++a)
          for (unsigned int b = a; b < 3; ++b)
            eps[a][b] = 0.5 * (inputs.solution_gradients[p][a][b] +
                               inputs.solution_gradients[p][b][a]);
        if (bbar)
          eps = PlateModel::with_dilatation(eps, theta);
        eps -= profile.thermal_strain(z) * unit_symmetric_tensor<3>();
        const SymmetricTensor<2, 3> sigma = HookeLaw::stress(E, nu, eps);
        computed_quantities[p][0]         = profile.temperature(z);
        computed_quantities[p][1]         = profile.thermal_expansion(z);
        for (unsigned int a = 0; a < 3; ++a)
          for (unsigned int b = 0; b < 3; ++b)
            computed_quantities[p][2 + 3 * a + b] = sigma[a][b] * 1e-6;
      }
  }



  void
  VtuWriter::set_prestress(const InitialStress &initial_stress)
  {
    initial = &initial_stress;
    if (recovery)
      recovery->set_prestress(initial_stress);
    postprocessor.set_prestress(initial_stress);
    if (fields.thermal)
      thermal = std::make_unique<ThermalPostprocessor>(plate, initial_stress);
  }



  void
  VtuWriter::add_thermal_fields(DataOut<3> &data_out)
  {
    if (!thermal)
      return;
    data_out.add_data_vector(
      initial->displacement(),
      std::vector<std::string>(3, "thermal_displacement_m"),
      DataOut<3>::type_dof_data,
      std::vector<DataComponentInterpretation::DataComponentInterpretation>(
        3, DataComponentInterpretation::component_is_part_of_vector));
    data_out.add_data_vector(initial->displacement(), *thermal);
  }
} // namespace fgimpact
