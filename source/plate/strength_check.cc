// The elastic stresses against the graded strengths at every step
// (strength_check.h).

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/base/symmetric_tensor.h>

#include <deal.II/fe/fe_values.h>

#include <fgimpact/material/constitutive_law.h>
#include <fgimpact/plate/strength_check.h>

#include <array>
#include <cmath>
#include <limits>
#include <map>

namespace fgimpact
{
  StrengthCheck::StrengthCheck(const PlateModel     &plate,
                               const GradedStrength &strength,
                               const Point<3>       &excluded_centre,
                               const double          excluded_radius)
    : plate(plate)
    , strength(strength)
  {
    u_ghosted.reinit(plate.locally_owned_dofs(),
                     plate.locally_relevant_dofs(),
                     plate.get_mpi_communicator());
    setup(excluded_centre, excluded_radius);
  }



  void
  StrengthCheck::setup(const Point<3> &excluded_centre,
                       const double    excluded_radius)
  {
    const auto                &fe        = plate.get_fe();
    const FiniteElement<3>    &scalar_fe = fe.base_element(0);
    const Quadrature<3>        support(scalar_fe.get_unit_support_points());
    FEValues<3>                fe_values(plate.get_mapping(),
                          fe,
                          support,
                          update_gradients | update_quadrature_points);
    const PropertyInterpolator properties(scalar_fe,
                                          support.get_points(),
                                          plate.get_material());
    const unsigned int         n_dofs = fe.n_dofs_per_cell();
    n_points = n_scalar = support.size();
    unit_support        = support.get_points();

    const auto &map = u_ghosted.trilinos_vector().Map();
    std::map<std::array<double, 3>, unsigned int> tables;
    std::vector<types::global_dof_index>          dofs(n_dofs);
    std::vector<double>                           E, nu, rho;
    std::vector<int>                              cell_index(n_dofs);
    for (const auto &cell : plate.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          bool excluded = false;
          for (const unsigned int v : cell->vertex_indices())
            excluded = excluded || cell->vertex(v).distance(excluded_centre) <
                                     excluded_radius;
          if (excluded)
            continue;
          fe_values.reinit(cell);
          const std::array<double, 3> extent = {{cell->extent_in_direction(0),
                                                 cell->extent_in_direction(1),
                                                 cell->extent_in_direction(2)}};
          const auto [it, added] = tables.emplace(extent, gradients.size());
          if (added)
            add_table(cell, fe_values, extent);
          if (plate.uses_incompatible_modes())
            add_mode_table(cell, extent);
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < n_dofs; ++i)
            {
              const auto [c, s]     = fe.system_to_component_index(i);
              cell_index[s * 3 + c] = map.LID(
                static_cast<TrilinosWrappers::types::int_type>(dofs[i]));
            }
          table.push_back(it->second);
          active_index.push_back(cell->active_cell_index());
          local_index.insert(local_index.end(),
                             cell_index.begin(),
                             cell_index.end());
          properties.values(cell, E, nu, rho);
          factors.emplace_back();
          for (unsigned int q = 0; q < n_points; ++q)
            add_point(fe_values.quadrature_point(q), E[q], nu[q]);
        }
    set_gradient_bounds();
  }



  void
  StrengthCheck::add_table(const DoFHandler<3>::active_cell_iterator &cell,
                           const FEValues<3>                         &fe_values,
                           const std::array<double, 3>               &extent)
  {
    // The cells of one extent share their shape gradients (the mapping is
    // affine: boxes) and their mean divergence (B-bar).
    const auto        &fe     = plate.get_fe();
    const unsigned int n_dofs = fe.n_dofs_per_cell();
    gradients.emplace_back(n_points * n_scalar * 3);
    gradient_bound.push_back(0.);
    extents.push_back(extent);
    mean_divergences.emplace_back();
    const auto m = plate.mean_divergence(cell);
    for (unsigned int i = 0; i < m.size(); ++i)
      {
        const auto [c, s] = fe.system_to_component_index(i);
        mean_divergences.back().resize(n_dofs);
        mean_divergences.back()[s * 3 + c] = m[i];
      }
    for (unsigned int i = 0; i < n_dofs; ++i)
      {
        const auto [c, s] = fe.system_to_component_index(i);
        for (unsigned int q = 0; q < n_points; ++q)
          for (unsigned int d = 0; d < 3; ++d)
            gradients.back()[(q * n_scalar + s) * 3 + d] =
              fe_values.shape_grad_component(i, q, c)[d];
      }
  }



  void
  StrengthCheck::set_gradient_bounds()
  {
    // |grad u| <= |D| max_q |sum_s |grad N_s(x_q)|| (can_skip()).
    for (unsigned int t = 0; t < gradients.size(); ++t)
      for (unsigned int q = 0; q < n_points; ++q)
        {
          double A[3] = {};
          for (unsigned int s = 0; s < n_scalar; ++s)
            for (unsigned int d = 0; d < 3; ++d)
              A[d] += std::abs(gradients[t][(q * n_scalar + s) * 3 + d]);
          gradient_bound[t] =
            std::max(gradient_bound[t],
                     std::sqrt(A[0] * A[0] + A[1] * A[1] + A[2] * A[2]));
        }
  }



  void
  StrengthCheck::add_point(const Point<3> &x, const double E, const double nu)
  {
    const bool   is_metal = strength.metal_rich(x[2]);
    const double S        = is_metal ?
                              (strength.get_parameters().metal_yield_strength > 0. ?
                                 strength.yield_strength(x[2]) :
                                 0.) :
                              strength.tensile_strength(x[2]);
    lambda.push_back(HookeLaw::lambda(E, nu));
    two_mu.push_back(2. * HookeLaw::mu(E, nu));
    inverse_strength.push_back(S > 0. ? 1. / S : 0.);
    // von Mises = 2 mu sqrt(3/2) |dev eps|; sigma_1 = lambda tr eps +
    // 2 mu eps_1 <= (lambda + 2 mu/3) |tr eps| + 2 mu sqrt(2/3) |dev eps|
    // <= (sqrt(3) |lambda| + 2 mu) |eps|.
    const double invS = inverse_strength.back(), l = std::abs(lambda.back()),
                 m2 = two_mu.back();
    CellFactors &f  = factors.back();
    if (is_metal)
      f.metal = std::max(f.metal, m2 * std::sqrt(1.5) * invS);
    else
      {
        f.ceramic_trace = std::max(f.ceramic_trace, (l + m2 / 3.) * invS);
        f.ceramic_deviator =
          std::max(f.ceramic_deviator, m2 * std::sqrt(2. / 3.) * invS);
        f.ceramic_norm =
          std::max(f.ceramic_norm, (std::sqrt(3.) * l + m2) * invS);
      }
    metal.push_back(is_metal);
    points.push_back(x);
    if (S > 0.)
      ++(is_metal ? n_metal : n_ceramic);
  }



  void
  StrengthCheck::evaluate(const TrilinosWrappers::MPI::Vector &u,
                          const double                         t)
  {
    const double *const values = gather(u);
    const unsigned int  n_dofs = 3 * n_scalar;
    std::vector<double> cell_u(n_dofs);
    for (unsigned int c = 0; c < table.size(); ++c)
      {
        for (unsigned int i = 0; i < n_dofs; ++i)
          cell_u[i] = values[local_index[c * n_dofs + i]];
        // A cell with plastic strain is not bounded by its elastic strain.
        const bool plastic_cell =
          plasticity && plasticity->holds_plastic_strain(active_index[c]);
        std::array<double, 9> alpha{};
        const bool            modes = mode_amplitudes(c, cell_u, alpha);
        if (!plastic_cell && can_skip(c, cell_u, modes ? &alpha : nullptr))
          continue;
        const auto &m     = mean_divergences[table[c]];
        double      theta = 0; // B-bar: the cell's mean dilatation
        for (unsigned int i = 0; i < m.size(); ++i)
          theta += m[i] * cell_u[i];
        for (unsigned int q = 0; q < n_points; ++q)
          {
            const unsigned int k = c * n_points + q;
            if (inverse_strength[k] == 0.)
              continue;
            double G[3][3];
            displacement_gradient(
              c, q, cell_u, m.empty() ? nullptr : &theta, G);
            if (modes)
              add_mode_gradient(c, q, alpha, G);
            double yield_stress = 0.;
            if (plasticity && metal[k])
              yield_stress = plasticity->yield_stress(points[k][2], 0.);
            if (plastic_cell)
              {
                // eps - eps_p: the symmetric part of G loses eps_p.
                const PlasticState state =
                  plasticity->plastic_state(active_index[c], unit_support[q]);
                for (unsigned int a = 0; a < 3; ++a)
                  for (unsigned int d = 0; d < 3; ++d)
                    G[a][d] -= state.plastic_strain[a][d];
                if (metal[k])
                  yield_stress =
                    plasticity->yield_stress(points[k][2],
                                             state.equivalent_plastic_strain);
              }
            if (!prestrain.empty())
              add_prestrain(k, G);
            check_point(k, G, t, yield_stress);
          }
      }
  }



  void
  StrengthCheck::displacement_gradient(const unsigned int         c,
                                       const unsigned int         q,
                                       const std::vector<double> &cell_u,
                                       const double *const        theta,
                                       double                     G[3][3]) const
  {
    // G_cd = sum_s u_sc dN_s/dx_d.
    const double *const grad = gradients[table[c]].data();
    for (unsigned int a = 0; a < 3; ++a)
      for (unsigned int d = 0; d < 3; ++d)
        G[a][d] = 0.;
    for (unsigned int s = 0; s < n_scalar; ++s)
      {
        const double *const g  = grad + (q * n_scalar + s) * 3;
        const double *const us = cell_u.data() + 3 * s;
        for (unsigned int a = 0; a < 3; ++a)
          for (unsigned int d = 0; d < 3; ++d)
            G[a][d] += us[a] * g[d];
      }
    if (theta != nullptr) // B-bar: the trace is the cell's mean
      {
        const double shift = (*theta - G[0][0] - G[1][1] - G[2][2]) / 3.;
        for (unsigned int a = 0; a < 3; ++a)
          G[a][a] += shift;
      }
  }



  namespace
  {
    /// Any Lagrange element: |grad u| <= |D| gradient_bound with D_a =
    /// max_s |u_sa - mean_s u_sa| (the shape functions sum to 1); |D| (m).
    double
    displacement_spread(const std::vector<double> &cell_u,
                        const unsigned int         n_scalar)
    {
      double D2 = 0;
      for (unsigned int a = 0; a < 3; ++a)
        {
          double mean = 0, D = 0;
          for (unsigned int s = 0; s < n_scalar; ++s)
            mean += cell_u[3 * s + a] / n_scalar;
          for (unsigned int s = 0; s < n_scalar; ++s)
            D = std::max(D, std::abs(cell_u[3 * s + a] - mean));
          D2 += D * D;
        }
      return std::sqrt(D2);
    }

    /// Q1 on a brick of extents h (m), unit coordinates x^ in [-1, 1]^3,
    /// vertex v = i + 2j + 4k at (2i - 1, 2j - 1, 2k - 1): u = sum of c_m
    /// monomials, so du/dx = 2/dx (c_x + c_xy y^ + c_xz z^ + c_xyz y^ z^),
    /// whose centre value G is exact and whose variation is at most 2/dx
    /// (|c_xy| + |c_xz| + |c_xyz|); likewise in y and z.  variation2: the
    /// sum of the squared variations.
    void
    q1_centre_gradient(const std::vector<double>   &cell_u,
                       const std::array<double, 3> &h,
                       const std::array<double, 9> *alpha,
                       double                       G[3][3],
                       double                      &variation2)
    {
      for (unsigned int a = 0; a < 3; ++a)
        {
          double m[7] = {}; // x, y, z, xy, xz, yz, xyz
          for (unsigned int v = 0; v < 8; ++v)
            {
              const double sx = (v & 1) ? 1. : -1., sy = (v & 2) ? 1. : -1.,
                           sz = (v & 4) ? 1. : -1., u = cell_u[3 * v + a] / 8.;
              m[0] += sx * u;
              m[1] += sy * u;
              m[2] += sz * u;
              m[3] += sx * sy * u;
              m[4] += sx * sz * u;
              m[5] += sy * sz * u;
              m[6] += sx * sy * sz * u;
            }
          const double var[3] = {
            std::abs(m[3]) + std::abs(m[4]) + std::abs(m[6]),
            std::abs(m[3]) + std::abs(m[5]) + std::abs(m[6]),
            std::abs(m[4]) + std::abs(m[5]) + std::abs(m[6])};
          for (unsigned int d = 0; d < 3; ++d)
            {
              G[a][d] = 2. / h[d] * m[d];
              // Incompatible mode (a, d): gradient -4 xi_d alpha / h_d.
              const double modes =
                alpha ? 4. * std::abs((*alpha)[3 * a + d]) : 0.;
              variation2 += std::pow((2. * var[d] + modes) / h[d], 2);
            }
        }
    }
  } // namespace



  bool
  StrengthCheck::can_skip(const unsigned int           c,
                          const std::vector<double>   &cell_u,
                          const std::array<double, 9> *alpha) const
  {
    const CellFactors &f = factors[c];
    if (n_scalar != 8)
      {
        const double bound =
          displacement_spread(cell_u, n_scalar) * gradient_bound[table[c]] +
          (prestrain.empty() ? 0. : prestrain_norm[c]);
        return bound * f.metal <= metal_local.ratio &&
               bound * f.ceramic_norm <= ceramic_local.ratio;
      }
    double G[3][3], variation2 = 0;
    q1_centre_gradient(cell_u, extents[table[c]], alpha, G, variation2);
    const double tr   = G[0][0] + G[1][1] + G[2][2];
    double       dev2 = 0;
    for (unsigned int a = 0; a < 3; ++a)
      for (unsigned int b = 0; b < 3; ++b)
        dev2 +=
          std::pow(0.5 * (G[a][b] + G[b][a]) - (a == b ? tr / 3. : 0.), 2);
    // |eps(x) - eps_c| <= |grad u(x) - grad u_c| <= sqrt(variation2), and
    // |tr| changes by at most sqrt(3) times that.
    const double V = std::sqrt(variation2);
    // A pre-stress: its strain's largest deviator and trace in the cell.
    const double dev0 = prestrain.empty() ? 0. : prestrain_dev[c],
                 tr0  = prestrain.empty() ? 0. : prestrain_trace[c];
    const double dev  = std::sqrt(dev2) + V + dev0;
    return f.metal * dev <= metal_local.ratio &&
           f.ceramic_trace * (std::abs(tr) + std::sqrt(3.) * V + tr0) +
               f.ceramic_deviator * dev <=
             ceramic_local.ratio;
  }



  void
  StrengthCheck::set_plasticity(const PlasticPlate &plastic)
  {
    plasticity = &plastic;
  }



  void
  StrengthCheck::check_point(const unsigned int k,
                             const double       G[3][3],
                             const double       t,
                             const double       yield_stress)
  {
    // sigma = lambda tr(eps) 1 + 2 mu eps: von Mises = 2 mu sqrt(3/2)
    // |dev eps|, and sigma_1 = lambda tr(eps) + 2 mu eps_1 with
    // eps_1 <= tr/3 + sqrt(2/3) |dev eps|: the eigenvalues only where that
    // bound can beat the peak.
    const double tr  = G[0][0] + G[1][1] + G[2][2];
    const double e01 = 0.5 * (G[0][1] + G[1][0]),
                 e02 = 0.5 * (G[0][2] + G[2][0]),
                 e12 = 0.5 * (G[1][2] + G[2][1]);
    const double d0 = G[0][0] - tr / 3., d1 = G[1][1] - tr / 3.,
                 d2    = G[2][2] - tr / 3.;
    const double  dev  = std::sqrt(d0 * d0 + d1 * d1 + d2 * d2 +
                                 2. * (e01 * e01 + e02 * e02 + e12 * e12));
    StrengthPeak &peak = metal[k] ? metal_local : ceramic_local;
    double        stress;
    if (metal[k])
      {
        stress = two_mu[k] * std::sqrt(1.5) * dev;
        // A plastic run: the extrapolated stress returned onto the yield
        // surface, as the VTU's (J2Plasticity::admissible_stress()).
        if (yield_stress > 0.)
          stress = std::min(stress, yield_stress);
      }
    else
      {
        const double mean = lambda[k] * tr + two_mu[k] * tr / 3.;
        if ((mean + two_mu[k] * std::sqrt(2. / 3.) * dev) *
              inverse_strength[k] <=
            peak.ratio)
          return;
        SymmetricTensor<2, 3> eps;
        eps[0][0] = G[0][0];
        eps[1][1] = G[1][1];
        eps[2][2] = G[2][2];
        eps[0][1] = e01;
        eps[0][2] = e02;
        eps[1][2] = e12;
        stress    = lambda[k] * tr + two_mu[k] * eigenvalues(eps)[0];
      }
    const double inverse =
      yield_stress > 0. ? 1. / yield_stress : inverse_strength[k];
    const double       ratio = stress * inverse;
    const StrengthPeak candidate{ratio, stress, 1. / inverse, points[k], t};
    if (precedes(candidate, peak))
      peak = candidate;
  }



  bool
  StrengthCheck::precedes(const StrengthPeak &a, const StrengthPeak &b)
  {
    // Mirror-image points of a symmetric scene tie to round-off: within a
    // relative 1e-12 the smaller (x, y, z), then the earlier time, wins,
    // whatever the order of the cells and ranks.
    const double tolerance =
      1e-12 * std::max(std::abs(a.ratio), std::abs(b.ratio));
    if (std::abs(a.ratio - b.ratio) > tolerance)
      return a.ratio > b.ratio;
    for (unsigned int d = 0; d < 3; ++d)
      if (std::abs(a.point[d] - b.point[d]) > 1e-12)
        return a.point[d] < b.point[d];
    return a.time < b.time;
  }



  StrengthPeak
  StrengthCheck::global_peak(const StrengthPeak &local,
                             const unsigned int  n_local) const
  {
    const MPI_Comm comm = plate.get_mpi_communicator();
    if (Utilities::MPI::sum(n_local, comm) == 0)
      {
        return StrengthPeak::unchecked();
      }
    // Every rank's peak, then the same choice on every rank (so the
    // point does not depend on the partition).
    const auto   all  = Utilities::MPI::all_gather(comm, local);
    StrengthPeak best = all[0];
    for (const auto &peak : all)
      if (precedes(peak, best))
        best = peak;
    return best;
  }



  StrengthPeak
  StrengthCheck::metal_peak() const
  {
    return global_peak(metal_local, n_metal);
  }



  StrengthPeak
  StrengthCheck::ceramic_peak() const
  {
    return global_peak(ceramic_local, n_ceramic);
  }



  void
  StrengthCheck::set_peaks(const StrengthPeak &metal,
                           const StrengthPeak &ceramic)
  {
    metal_local   = metal;
    ceramic_local = ceramic;
  }
} // namespace fgimpact
