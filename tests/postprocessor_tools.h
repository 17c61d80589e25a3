// What StressPostprocessor (the VTU's cell stress) writes at one point of
// one cell, for the tests that compare it with the probes.

#ifndef fgimpact_tests_postprocessor_tools_h
#define fgimpact_tests_postprocessor_tools_h

#include <deal.II/base/quadrature.h>

#include <deal.II/fe/fe_values.h>

#include <fgimpact/output/postprocessing.h>

#include <vector>

namespace fgimpact_tests
{
  /// The postprocessor's 3 x 3 stress (its first 9 outputs, MPa) at the
  /// unit point `unit` of `cell`, from the ghosted displacement.
  inline dealii::SymmetricTensor<2, 3>
  postprocessed_stress(const fgimpact::PlateModel          &plate,
                       const fgimpact::StressPostprocessor &postprocessor,
                       const dealii::TrilinosWrappers::MPI::Vector &u_ghosted,
                       const dealii::DoFHandler<3>::active_cell_iterator &cell,
                       const dealii::Point<3>                            &unit)
  {
    using namespace dealii;
    FEValues<3> fe_values(plate.get_mapping(),
                          plate.get_fe(),
                          Quadrature<3>(std::vector<Point<3>>{unit}),
                          update_gradients | update_quadrature_points);
    fe_values.reinit(cell);
    DataPostprocessorInputs::Vector<3> inputs;
    inputs.solution_gradients.resize(1, std::vector<Tensor<1, 3>>(3));
    fe_values.get_function_gradients(u_ghosted, inputs.solution_gradients);
    inputs.evaluation_points = {fe_values.quadrature_point(0)};
    inputs.template set_cell<3>(cell);
    std::vector<Vector<double>> out(
      1, Vector<double>(postprocessor.get_names().size()));
    postprocessor.evaluate_vector_field(inputs, out);
    SymmetricTensor<2, 3> sigma;
    for (unsigned int a = 0; a < 3; ++a)
      for (unsigned int b = a; b < 3; ++b)
        sigma[a][b] = out[0][3 * a + b];
    return sigma;
  }
} // namespace fgimpact_tests

#endif
