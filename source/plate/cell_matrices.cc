#include <deal.II/base/tensor.h>

#include <fgimpact/material/constitutive_law.h>
#include <fgimpact/plate/cell_matrices.h>

namespace fgimpact
{
  void
  add_elastic_cell_matrices(const FEValues<3>         &fe_values,
                            const std::vector<double> &E,
                            const std::vector<double> &nu,
                            const std::vector<double> &rho,
                            FullMatrix<double>        &cell_K,
                            FullMatrix<double>        &cell_M)
  {
    const FiniteElement<3> &fe            = fe_values.get_fe();
    const unsigned int      dofs_per_cell = fe.n_dofs_per_cell();
    for (unsigned int q = 0; q < fe_values.n_quadrature_points; ++q)
      {
        const double lambda = HookeLaw::lambda(E[q], nu[q]);
        const double mu     = HookeLaw::mu(E[q], nu[q]);
        const double JxW    = fe_values.JxW(q);
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
          {
            const unsigned int ci     = fe.system_to_component_index(i).first;
            const Tensor<1, 3> grad_i = fe_values.shape_grad(i, q);
            const double       phi_i  = fe_values.shape_value(i, q);
            for (unsigned int j = 0; j < dofs_per_cell; ++j)
              {
                const unsigned int cj = fe.system_to_component_index(j).first;
                const Tensor<1, 3> grad_j = fe_values.shape_grad(j, q);
                double             k_ij   = lambda * grad_i[ci] * grad_j[cj] +
                              mu * grad_i[cj] * grad_j[ci];
                if (ci == cj)
                  {
                    k_ij += mu * (grad_i * grad_j);
                    cell_M(i, j) +=
                      rho[q] * phi_i * fe_values.shape_value(j, q) * JxW;
                  }
                cell_K(i, j) += k_ij * JxW;
              }
          }
      }
  }



  void
  add_geometric_cell_matrix(const FEValues<3>                        &fe_values,
                            const std::vector<SymmetricTensor<2, 3>> &sigma0,
                            FullMatrix<double>                       &cell_K)
  {
    const FiniteElement<3> &fe = fe_values.get_fe();
    const unsigned int      n  = fe.n_dofs_per_cell();
    for (unsigned int q = 0; q < fe_values.n_quadrature_points; ++q)
      for (unsigned int i = 0; i < n; ++i)
        {
          const Tensor<1, 3> s_grad_i =
            sigma0[q] * fe_values.shape_grad(i, q) * fe_values.JxW(q);
          const unsigned int ci = fe.system_to_component_index(i).first;
          for (unsigned int j = 0; j < n; ++j)
            if (fe.system_to_component_index(j).first == ci)
              cell_K(i, j) += s_grad_i * fe_values.shape_grad(j, q);
        }
  }



  void
  add_cell_mass_product(const FEValues<3>         &fe_values,
                        const std::vector<double> &rho,
                        const Vector<double>      &d,
                        Vector<double>            &cell_r)
  {
    const FiniteElement<3> &fe = fe_values.get_fe();
    for (unsigned int q = 0; q < fe_values.n_quadrature_points; ++q)
      for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
        for (unsigned int j = 0; j < fe.n_dofs_per_cell(); ++j)
          if (d[j] != 0. && fe.system_to_component_index(i).first ==
                              fe.system_to_component_index(j).first)
            cell_r[i] += rho[q] * fe_values.shape_value(i, q) *
                         fe_values.shape_value(j, q) * d[j] * fe_values.JxW(q);
  }
} // namespace fgimpact
