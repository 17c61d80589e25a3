#include <deal.II/base/quadrature.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/grid/grid_tools.h>

#include <fgimpact/probes.h>

#include <map>

namespace fgimpact
{
  namespace
  {
    constexpr unsigned int voigt[6][2] =
      {{0, 0}, {1, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}};
  }



  PointProbe::PointProbe(const PlateModel &plate, const Point<3> &location)
    : point(location)
  {
    const auto &dof_handler = plate.get_dof_handler();
    const auto &fe          = plate.get_fe();
    const auto  cells       = GridTools::find_all_active_cells_around_point(
      plate.get_mapping(), dof_handler, location, 1e-10);
    AssertThrow(!cells.empty(),
                ExcMessage("A probe point lies outside the plate."));
    n_adjacent_cells = cells.size();

    const double lambda_per_E = plate.get_material().lambda_per_E();
    const double mu_per_E     = plate.get_material().mu_per_E();

    std::array<std::map<types::global_dof_index, double>, 3> disp;
    std::array<std::map<types::global_dof_index, double>, 6> stress;
    std::vector<types::global_dof_index> local_dofs(fe.n_dofs_per_cell());

    for (const auto &[cell, unit_point] : cells)
      {
        const Quadrature<3> quadrature(std::vector<Point<3>>{
          GeometryInfo<3>::project_to_unit_cell(unit_point)});
        FEValues<3>         fe_values(plate.get_mapping(),
                              fe,
                              quadrature,
                              update_values | update_gradients);
        fe_values.reinit(cell);
        cell->get_dof_indices(local_dofs);

        std::vector<double>  E, rho;
        PropertyInterpolator properties(fe.base_element(0),
                                        quadrature.get_points(),
                                        plate.get_material());
        properties.values(cell, E, rho);
        const double lambda = lambda_per_E * E[0];
        const double mu     = mu_per_E * E[0];
        const double w      = 1. / cells.size();

        for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
          {
            const unsigned int c = fe.system_to_component_index(i).first;
            const auto         g = fe_values.shape_grad(i, 0);
            // The displacement is continuous: each cell gives the same
            // value, so averaging is harmless.
            disp[c][local_dofs[i]] += w * fe_values.shape_value(i, 0);
            // sigma_ab = lambda g_c delta_ab + mu (delta_ac g_b + delta_bc g_a)
            for (unsigned int s = 0; s < 6; ++s)
              {
                const unsigned int a = voigt[s][0], b = voigt[s][1];
                double             value = 0;
                if (a == b)
                  value += lambda * g[c];
                if (a == c)
                  value += mu * g[b];
                if (b == c)
                  value += mu * g[a];
                if (value != 0.)
                  stress[s][local_dofs[i]] += w * value;
              }
          }
      }

    for (unsigned int c = 0; c < 3; ++c)
      for (const auto &entry : disp[c])
        if (entry.second != 0.)
          displacement_weights[c].push_back(entry);
    for (unsigned int s = 0; s < 6; ++s)
      stress_weights[s].assign(stress[s].begin(), stress[s].end());
  }



  double
  PointProbe::apply(const Weights &w, const TrilinosWrappers::MPI::Vector &u)
  {
    double result = 0;
    for (const auto &[dof, weight] : w)
      result += weight * u(dof);
    return result;
  }



  Tensor<1, 3>
  PointProbe::displacement(const TrilinosWrappers::MPI::Vector &u) const
  {
    Tensor<1, 3> d;
    for (unsigned int c = 0; c < 3; ++c)
      d[c] = apply(displacement_weights[c], u);
    return d;
  }



  SymmetricTensor<2, 3>
  PointProbe::stress(const TrilinosWrappers::MPI::Vector &u) const
  {
    SymmetricTensor<2, 3> sigma;
    for (unsigned int s = 0; s < 6; ++s)
      sigma[voigt[s][0]][voigt[s][1]] = apply(stress_weights[s], u);
    return sigma;
  }
} // namespace fgimpact
