// The B-bar (mean dilatation) brick of PlateModel: its stiffness and the
// weights of the cell's mean dilatation (plate_model.h).

#include <fgimpact/material/constitutive_law.h>
#include <fgimpact/plate/plate_model.h>

namespace fgimpact
{
  void
  PlateModel::replace_dilatation(
    const FEValues<3>                         &fe_values,
    const std::vector<double>                 &E,
    const std::vector<double>                 &nu,
    const DoFHandler<3>::active_cell_iterator &cell,
    FullMatrix<double>                        &cell_K)
  {
    // K_ij = int kappa div_i div_j + 2 mu dev eps_i : dev eps_j with
    // kappa = lambda + 2 mu / 3; B-bar replaces div_i div_j by the cell
    // means: K_ij - int kappa div_i div_j + (int kappa) m_i m_j.
    const unsigned int n      = fe.n_dofs_per_cell();
    double             volume = 0, kappa_sum = 0;
    double *const      mean_div =
      mean_divergences.data() + cell->active_cell_index() * n;
    for (unsigned int q = 0; q < fe_values.n_quadrature_points; ++q)
      {
        const double kappa =
          HookeLaw::lambda(E[q], nu[q]) + 2. / 3. * HookeLaw::mu(E[q], nu[q]);
        const double JxW = fe_values.JxW(q);
        volume += JxW;
        kappa_sum += kappa * JxW;
        for (unsigned int i = 0; i < n; ++i)
          {
            const unsigned int ci  = fe.system_to_component_index(i).first;
            const double       d_i = fe_values.shape_grad(i, q)[ci];
            mean_div[i] += d_i * JxW;
            for (unsigned int j = 0; j < n; ++j)
              {
                const unsigned int cj = fe.system_to_component_index(j).first;
                cell_K(i, j) -=
                  kappa * d_i * fe_values.shape_grad(j, q)[cj] * JxW;
              }
          }
      }
    for (unsigned int i = 0; i < n; ++i)
      mean_div[i] /= volume;
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        cell_K(i, j) += kappa_sum * mean_div[i] * mean_div[j];
  }



  ArrayView<const double>
  PlateModel::mean_divergence(
    const DoFHandler<3>::active_cell_iterator &cell) const
  {
    if (mean_divergences.empty())
      return {};
    const unsigned int n = fe.n_dofs_per_cell();
    return {mean_divergences.data() + cell->active_cell_index() * n, n};
  }



  double
  PlateModel::mean_dilatation(const DoFHandler<3>::active_cell_iterator &cell,
                              const TrilinosWrappers::MPI::Vector &u) const
  {
    const auto weights = mean_divergence(cell);
    if (weights.size() == 0)
      return 0.;
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    cell->get_dof_indices(dofs);
    double theta = 0;
    for (unsigned int i = 0; i < dofs.size(); ++i)
      theta += weights[i] * u(dofs[i]);
    return theta;
  }


  void
  PlateModel::apply_mean_dilatation(
    const DoFHandler<3>::active_cell_iterator &cell,
    const TrilinosWrappers::MPI::Vector       &u,
    std::vector<SymmetricTensor<2, 3>>        &eps) const
  {
    if (!parameters.mean_dilatation)
      return;
    const double theta = mean_dilatation(cell, u);
    for (auto &e : eps)
      e = with_dilatation(e, theta);
  }
} // namespace fgimpact
