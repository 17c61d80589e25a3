// The support reaction of the probes (ProbeSet, probe_set.h): the weights
// that make the supports' share of the internal force, hanging nodes'
// shares included, a linear functional of the fields, and a plastic
// plate's correction of it.

#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>

#include <fgimpact/material/constitutive_law.h>
#include <fgimpact/plate/probe_set.h>
#include <fgimpact/plate/probes.h>

#include <array>
#include <cmath>
#include <utility>

namespace fgimpact
{
  namespace
  {
    /// z_S at a z DoF: 1 if fixed at 0 (constrained, no entries), the
    /// weight of its fixed masters if it hangs (1 minus its entries'), else 0.
    double
    support_weight(const AffineConstraints<double> &constraints,
                   const types::global_dof_index    dof)
    {
      if (!constraints.is_constrained(dof))
        return 0.;
      const auto *entries = constraints.get_constraint_entries(dof);
      double      free    = 0;
      if (entries != nullptr)
        for (const auto &[master, weight] : *entries)
          free += weight;
      return std::abs(1. - free) < 1e-12 ? 0. : 1. - free;
    }

    /// z_S's nodal values on a cell (support_weight() of its z DoFs, 0
    /// for x and y): whether any is not 0.
    bool
    support_weights(const AffineConstraints<double>            &constraints,
                    const FiniteElement<3>                     &fe,
                    const std::vector<types::global_dof_index> &dofs,
                    std::vector<double>                        &supported)
    {
      bool any = false;
      for (unsigned int i = 0; i < dofs.size(); ++i)
        {
          supported[i] = fe.system_to_component_index(i).first == 2 ?
                           support_weight(constraints, dofs[i]) :
                           0.;
          any          = any || supported[i] > 0.;
        }
      return any;
    }

    /// z_S (the supports' conforming field, `supported` its nodal values)
    /// and its strain at quadrature point q; B-bar (mean_div not empty:
    /// the shape functions' cell means of div) with the cell's mean
    /// dilatation, and the incompatible modes' strain (modes: each DoF's
    /// at q, zero without), as the stiffness a(z_S, u) has it: the
    /// condensed a(z, u) is a(eps(z) + eps_modes(z), eps(u)), since the
    /// modes of u are orthogonal to every mode in the energy.
    std::pair<double, SymmetricTensor<2, 3>>
    supported_field(const FEValues<3>                        &fe_values,
                    const unsigned int                        q,
                    const std::vector<double>                &supported,
                    const ArrayView<const double>            &mean_div,
                    const std::vector<SymmetricTensor<2, 3>> &modes)
    {
      double                z_value = 0;
      SymmetricTensor<2, 3> eps_s;
      for (unsigned int i = 0; i < supported.size(); ++i)
        if (supported[i] > 0.)
          {
            z_value += supported[i] * fe_values.shape_value(i, q);
            const auto g = supported[i] * fe_values.shape_grad(i, q);
            for (unsigned int d = 0; d < 3; ++d)
              eps_s[2][d] += (d == 2 ? 1. : 0.5) * g[d];
          }
      if (mean_div.size() > 0)
        {
          double theta_s = 0;
          for (unsigned int i = 0; i < mean_div.size(); ++i)
            theta_s += supported[i] * mean_div[i];
          eps_s = PlateModel::with_dilatation(eps_s, theta_s);
        }
      for (unsigned int i = 0; i < supported.size(); ++i)
        eps_s += supported[i] * modes[i];
      return {z_value, eps_s};
    }

    /// Quadrature point q's share of the reaction weights: w[0](j) +=
    /// sigma(z_S) : eps(phi_j) JxW (B-bar: + (m_j - div phi_j) tr sigma /
    /// 3), w[1](j) += rho z_S phi_j JxW for the z DoFs (rho_z: rho z_S).
    void
    add_reaction_weights(const FEValues<3>                          &fe_values,
                         const unsigned int                          q,
                         const std::vector<types::global_dof_index> &dofs,
                         const SymmetricTensor<2, 3>                &sigma_s,
                         const double                                rho_z,
                         const ArrayView<const double>              &mean_div,
                         std::array<TrilinosWrappers::MPI::Vector, 2> &w)
    {
      const auto  &fe  = fe_values.get_fe();
      const double JxW = fe_values.JxW(q);
      for (unsigned int j = 0; j < dofs.size(); ++j)
        {
          const unsigned int c = fe.system_to_component_index(j).first;
          // sigma(z_S) : eps(phi_j) = sigma(z_S)[c] . grad N_j
          const auto g = fe_values.shape_grad(j, q);
          double     k = 0;
          for (unsigned int d = 0; d < 3; ++d)
            k += sigma_s[c][d] * g[d];
          if (mean_div.size() > 0)
            k += (mean_div[j] - g[c]) * trace(sigma_s) / 3.;
          w[0](dofs[j]) += k * JxW;
          if (c == 2)
            w[1](dofs[j]) += rho_z * fe_values.shape_value(j, q) * JxW;
        }
    }
  } // namespace



  void
  ProbeSet::setup_reaction_weights(const PlateModel &plate)
  {
    const auto                          &fe          = plate.get_fe();
    const auto                          &constraints = plate.get_constraints();
    const QGauss<3>                      quadrature(fe.degree + 1);
    FEValues<3>                          fe_values(plate.get_mapping(),
                          fe,
                          quadrature,
                          update_values | update_gradients | update_JxW_values);
    PropertyInterpolator                 properties(fe.base_element(0),
                                    quadrature.get_points(),
                                    plate.get_material());
    const HookeLaw                       hooke(plate.get_material());
    std::vector<double>                  E, nu, rho;
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    auto                                 w = weight_vectors<2>(plate);

    std::vector<double> supported(fe.n_dofs_per_cell());
    for (const auto &cell : plate.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(dofs);
          if (!support_weights(constraints, fe, dofs, supported))
            continue;
          fe_values.reinit(cell);
          properties.values(cell, E, nu, rho);
          // B-bar: the strains of z_S and of phi_j take the cell's mean
          // dilatation, as the stiffness a(z_S, u) does.
          const auto mean_div = plate.mean_divergence(cell);
          const auto modes =
            plate.mode_shape_strains(cell, quadrature.get_points());
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            {
              const auto [z_value, eps_s] =
                supported_field(fe_values, q, supported, mean_div, modes[q]);
              const SymmetricTensor<2, 3> sigma_s =
                hooke.stress(E[q], nu[q], eps_s);
              const double JxW = fe_values.JxW(q);
              reaction_points.push_back({cell->active_cell_index(),
                                         quadrature.point(q),
                                         sigma_s * JxW});
              add_reaction_weights(
                fe_values, q, dofs, sigma_s, z_value * rho[q], mean_div, w);
            }
        }
    const auto weights = owned_weights(plate, w);
    reaction_stiffness = weights[0];
    reaction_mass      = weights[1];
  }



  double
  ProbeSet::plastic_reaction() const
  {
    // The internal force of a plastic plate is K u - f_p, f_p = int B^T C
    // eps_p: its sum over the supported z DoFs is a(z_S, u) - int
    // sigma(z_S) : eps_p.  The plastic strain at a Gauss point is the
    // interpolant's value there (plastic_state() passes through them).
    double sum = 0;
    if (plastic != nullptr)
      for (const ReactionPoint &point : reaction_points)
        if (plastic->holds_plastic_strain(point.active_index))
          sum -= point.weighted_stress *
                 plastic->plastic_state(point.active_index, point.unit_point)
                   .plastic_strain;
    return sum;
  }
} // namespace fgimpact
