// Wilson-Taylor incompatible modes of the 8-node brick
// (incompatible_modes.h).

#include <deal.II/base/quadrature_lib.h>

#include <fgimpact/material/constitutive_law.h>
#include <fgimpact/plate/incompatible_modes.h>
#include <fgimpact/plate/plate_model.h>

#include <array>

namespace fgimpact
{
  namespace IncompatibleModes
  {
    Tensor<2, 3>
    centre_inverse_jacobian(const Triangulation<3>::cell_iterator &cell)
    {
      // Column l of J at the centre: the mean of the cell's four edges
      // along unit direction l (vertex v = i + 2 j + 4 k sits at (i, j,
      // k)).
      Tensor<2, 3> J;
      for (unsigned int l = 0; l < 3; ++l)
        for (unsigned int v = 0; v < 8; ++v)
          if ((v & (1u << l)) == 0)
            {
              const Tensor<1, 3> edge =
                cell->vertex(v | (1u << l)) - cell->vertex(v);
              for (unsigned int k = 0; k < 3; ++k)
                J[k][l] += 0.25 * edge[k];
            }
      // Taylor's centre Jacobian passes the patch test on parallelepipeds
      // only: every vertex is vertex 0 plus its unit coordinates times J.
      for (unsigned int v = 0; v < 8; ++v)
        {
          Tensor<1, 3> expected;
          for (unsigned int l = 0; l < 3; ++l)
            if ((v & (1u << l)) != 0)
              for (unsigned int k = 0; k < 3; ++k)
                expected[k] += J[k][l];
          (void)expected;
          Assert((cell->vertex(v) - cell->vertex(0) - expected).norm() <=
                   1e-10 * cell->diameter(),
                 ExcMessage("Incompatible modes need parallelepiped cells."));
        }
      return invert(J);
    }



    SymmetricTensor<2, 3>
    mode_strain(const unsigned int  a,
                const Point<3>     &unit_point,
                const Tensor<2, 3> &J0inv)
    {
      const unsigned int c = a / 3, d = a % 3;
      // N_d = 1 - xi_d^2 with xi = 2 xhat - 1: dN_d/dxhat_d = -4 xi_d.
      const double          dN = -4. * (2. * unit_point[d] - 1.);
      SymmetricTensor<2, 3> eps;
      for (unsigned int k = 0; k < 3; ++k)
        eps[c][k] += (c == k ? 1. : 0.5) * J0inv[d][k] * dN;
      return eps;
    }



    void
    condense(const FEValues<3>         &fe_values,
             const std::vector<double> &E,
             const std::vector<double> &nu,
             const Tensor<2, 3>        &J0inv,
             FullMatrix<double>        &cell_K,
             FullMatrix<double>        *H)
    {
      const unsigned int n = fe_values.get_fe().n_dofs_per_cell();
      FullMatrix<double> K_aa(n_modes, n_modes), K_au(n_modes, n);
      std::array<SymmetricTensor<2, 3>, n_modes> G, S;
      for (unsigned int q = 0; q < fe_values.n_quadrature_points; ++q)
        {
          const Point<3> &p   = fe_values.get_quadrature().point(q);
          const double    JxW = fe_values.JxW(q);
          for (unsigned int a = 0; a < n_modes; ++a)
            {
              G[a] = mode_strain(a, p, J0inv);
              S[a] = HookeLaw::stress(E[q], nu[q], G[a]) * JxW;
            }
          for (unsigned int a = 0; a < n_modes; ++a)
            {
              for (unsigned int b = 0; b < n_modes; ++b)
                K_aa(a, b) += S[a] * G[b];
              for (unsigned int j = 0; j < n; ++j)
                K_au(a, j) +=
                  S[a] * PlateModel::shape_strain(fe_values, j, q, {});
            }
        }
      K_aa.gauss_jordan(); // now K_aa^{-1}
      FullMatrix<double> H_local(n_modes, n);
      K_aa.mmult(H_local, K_au);
      H_local *= -1.;
      K_au.Tmmult(cell_K, H_local, /*adding=*/true);
      if (H != nullptr)
        *H = H_local;
    }
  } // namespace IncompatibleModes



  // PlateModel's incompatible modes (plate_model.h): the strains of the
  // stress paths. H is recomputed per cell where a path needs it (at an
  // output or in the set-up), not stored: 9 x 24 doubles a cell would be
  // 1.7 kB, more than the cell's share of K.

  FullMatrix<double>
  PlateModel::mode_amplitudes(
    const DoFHandler<3>::active_cell_iterator &cell) const
  {
    FullMatrix<double> H;
    if (!parameters.incompatible_modes)
      return H;
    const QGauss<3> quadrature(2);
    FEValues<3>     fe_values(mapping,
                          fe,
                          quadrature,
                          update_gradients | update_JxW_values);
    fe_values.reinit(cell);
    std::vector<double> E, nu, rho;
    PropertyInterpolator(fe.base_element(0), quadrature.get_points(), material)
      .values(cell, E, nu, rho);
    FullMatrix<double> scratch(fe.n_dofs_per_cell(), fe.n_dofs_per_cell());
    IncompatibleModes::condense(fe_values,
                                E,
                                nu,
                                IncompatibleModes::centre_inverse_jacobian(
                                  cell),
                                scratch,
                                &H);
    return H;
  }



  void
  PlateModel::add_mode_strains(const DoFHandler<3>::active_cell_iterator &cell,
                               const std::vector<Point<3>>         &unit_points,
                               const TrilinosWrappers::MPI::Vector &u,
                               std::vector<SymmetricTensor<2, 3>>  &eps) const
  {
    if (!parameters.incompatible_modes)
      return;
    const FullMatrix<double> H = mode_amplitudes(cell);
    Vector<double>           u_cell(fe.n_dofs_per_cell()),
      alpha(IncompatibleModes::n_modes);
    cell->get_dof_values(u, u_cell);
    H.vmult(alpha, u_cell);
    const Tensor<2, 3> J0inv = IncompatibleModes::centre_inverse_jacobian(cell);
    for (unsigned int k = 0; k < unit_points.size(); ++k)
      for (unsigned int a = 0; a < IncompatibleModes::n_modes; ++a)
        eps[k] +=
          alpha(a) * IncompatibleModes::mode_strain(a, unit_points[k], J0inv);
  }



  std::vector<std::vector<SymmetricTensor<2, 3>>>
  PlateModel::mode_shape_strains(
    const DoFHandler<3>::active_cell_iterator &cell,
    const std::vector<Point<3>>               &unit_points) const
  {
    std::vector<std::vector<SymmetricTensor<2, 3>>> strains(
      unit_points.size(),
      std::vector<SymmetricTensor<2, 3>>(fe.n_dofs_per_cell()));
    if (!parameters.incompatible_modes)
      return strains;
    const FullMatrix<double> H = mode_amplitudes(cell);
    const Tensor<2, 3> J0inv = IncompatibleModes::centre_inverse_jacobian(cell);
    for (unsigned int k = 0; k < unit_points.size(); ++k)
      for (unsigned int a = 0; a < IncompatibleModes::n_modes; ++a)
        {
          const SymmetricTensor<2, 3> G =
            IncompatibleModes::mode_strain(a, unit_points[k], J0inv);
          for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
            strains[k][i] += H(a, i) * G;
        }
    return strains;
  }
} // namespace fgimpact
