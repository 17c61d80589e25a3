#ifndef fgimpact_cell_matrices_h
#define fgimpact_cell_matrices_h

#include <deal.II/base/symmetric_tensor.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <vector>

namespace fgimpact
{
  using namespace dealii;

  /**
   * Add one cell's elastic stiffness and consistent mass to cell_K and
   * cell_M: at each quadrature point of fe_values (values, gradients and
   * JxW), step-8's component form of lambda div(phi_i) div(phi_j) + 2 mu
   * eps(phi_i):eps(phi_j), and rho phi_i phi_j for equal components, with
   * the graded E (Pa), nu and rho (kg/m^3) at the points.
   */
  void
  add_elastic_cell_matrices(const FEValues<3>         &fe_values,
                            const std::vector<double> &E,
                            const std::vector<double> &nu,
                            const std::vector<double> &rho,
                            FullMatrix<double>        &cell_K,
                            FullMatrix<double>        &cell_M);

  /**
   * Add one cell's initial-stress (geometric) stiffness to cell_K:
   * int grad(phi_i) . sigma0 grad(phi_j) dV for equal components, with
   * the pre-stress sigma0 (Pa) at each quadrature point of fe_values.  A
   * compressive sigma0 makes it negative: the plate softens in bending.
   */
  void
  add_geometric_cell_matrix(const FEValues<3>                        &fe_values,
                            const std::vector<SymmetricTensor<2, 3>> &sigma0,
                            FullMatrix<double>                       &cell_K);

  /// cell_r += M_K d: the cell's consistent mass (rho at the quadrature
  /// points of fe_values, kg/m^3) times a vector of its DoF values; zero
  /// entries of d are skipped.
  void
  add_cell_mass_product(const FEValues<3>         &fe_values,
                        const std::vector<double> &rho,
                        const Vector<double>      &d,
                        Vector<double>            &cell_r);
} // namespace fgimpact

#endif
