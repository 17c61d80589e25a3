// The plastic state of the plate at its Gauss points (plastic_plate.h).

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>

#include <fgimpact/material/constitutive_law.h>
#include <fgimpact/plate/plastic_plate.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace fgimpact
{
  double
  yield_crossing(const double before, const double after)
  {
    return after > before ?
             std::clamp((1. - before) / (after - before), 0., 1.) :
             1.;
  }



  void
  PlasticPlate::copy_owned(const TrilinosWrappers::MPI::Vector &from,
                           TrilinosWrappers::MPI::Vector       &to)
  {
    AssertThrow(from.locally_owned_size() == to.locally_owned_size(),
                ExcInternalError());
    std::copy(from.begin(), from.end(), to.begin());
  }



  PlasticPlate::PlasticPlate(const PlateModel     &plate,
                             const GradedStrength &strength)
    : plate(plate)
    , strength(strength)
  {
    u_ghosted.reinit(plate.locally_owned_dofs(),
                     plate.locally_relevant_dofs(),
                     plate.get_mpi_communicator());
    for (auto *v : {&u_distributed,
                    &force,
                    &new_force,
                    &residual,
                    &last_residual,
                    &committed_force})
      plate.initialize_vector(*v);
    setup();
  }



  void
  PlasticPlate::setup()
  {
    const auto                &fe = plate.get_fe();
    const QGauss<3>            quadrature(fe.degree + 1);
    FEValues<3>                fe_values(plate.get_mapping(),
                          fe,
                          quadrature,
                          update_gradients | update_quadrature_points |
                            update_JxW_values);
    const PropertyInterpolator properties(fe.base_element(0),
                                          quadrature.get_points(),
                                          plate.get_material());
    n_dofs   = fe.n_dofs_per_cell();
    n_points = quadrature.size();
    setup_interpolation(quadrature);
    cell_of_active.assign(
      plate.get_dof_handler().get_triangulation().n_active_cells(), -1);

    std::map<std::array<double, 3>, unsigned int> tables;
    std::vector<double>                           E, nu, rho;
    for (const auto &cell : plate.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          if (!any_metal_rich(fe_values))
            continue;
          const std::array<double, 3> extent = {{cell->extent_in_direction(0),
                                                 cell->extent_in_direction(1),
                                                 cell->extent_in_direction(2)}};
          const auto [it, added] = tables.emplace(extent, gradients.size());
          if (added)
            add_table(fe_values, quadrature, extent);
          add_cell_dofs(cell);
          cell_of_active[cell->active_cell_index()] = table.size();
          table.push_back(it->second);
          active_index.push_back(cell->active_cell_index());
          properties.values(cell, E, nu, rho);
          add_points(fe_values, E, nu);
        }
    committed.resize(yield.size());
    trial.resize(yield.size());
    trial_work.assign(yield.size(), 0.);
    trial_utilization.assign(yield.size(), 0.);
    utilization.assign(yield.size(), 0.);
    plastic_cell.assign(table.size(), false);
  }



  bool
  PlasticPlate::any_metal_rich(const FEValues<3> &fe_values) const
  {
    for (unsigned int q = 0; q < n_points; ++q)
      if (strength.metal_rich(fe_values.quadrature_point(q)[2]))
        return true;
    return false;
  }



  void
  PlasticPlate::add_cell_dofs(const DoFHandler<3>::active_cell_iterator &cell)
  {
    const auto &fe  = plate.get_fe();
    const auto &map = u_ghosted.trilinos_vector().Map();
    std::vector<types::global_dof_index> cell_dofs(n_dofs);
    cell->get_dof_indices(cell_dofs);
    dofs.insert(dofs.end(), cell_dofs.begin(), cell_dofs.end());
    const std::size_t first = local_index.size();
    local_index.resize(first + n_dofs);
    for (unsigned int i = 0; i < n_dofs; ++i)
      {
        const auto [c, s] = fe.system_to_component_index(i);
        local_index[first + s * 3 + c] =
          map.LID(static_cast<TrilinosWrappers::types::int_type>(cell_dofs[i]));
      }
  }



  void
  PlasticPlate::add_table(const FEValues<3>           &fe_values,
                          const Quadrature<3>         &quadrature,
                          const std::array<double, 3> &extent)
  {
    const auto         &fe        = plate.get_fe();
    const auto         &scalar_fe = fe.base_element(0);
    const unsigned int  n_scalar  = scalar_fe.n_dofs_per_cell();
    std::vector<double> g(n_points * n_scalar * 3), mean(n_scalar * 3, 0.),
      x(n_scalar * 3);
    for (unsigned int i = 0; i < n_dofs; ++i)
      {
        const auto [c, s] = fe.system_to_component_index(i);
        if (c != 0) // the scalar element's gradients, once
          continue;
        for (unsigned int d = 0; d < 3; ++d)
          {
            x[s * 3 + d] =
              (scalar_fe.unit_support_point(s)[d] - 0.5) * extent[d];
            for (unsigned int q = 0; q < n_points; ++q)
              {
                g[(q * n_scalar + s) * 3 + d] =
                  fe_values.shape_grad_component(i, q, 0)[d];
                mean[s * 3 + d] +=
                  quadrature.weight(q) * g[(q * n_scalar + s) * 3 + d];
              }
          }
      }
    // max_q |(sum_s |dN_s/dx_d|)_d|: |grad u - G| <= max_s |r_s| times it.
    double bound = 0;
    for (unsigned int q = 0; q < n_points; ++q)
      {
        double A[3] = {};
        for (unsigned int s = 0; s < n_scalar; ++s)
          for (unsigned int d = 0; d < 3; ++d)
            A[d] += std::abs(g[(q * n_scalar + s) * 3 + d]);
        bound =
          std::max(bound, std::sqrt(A[0] * A[0] + A[1] * A[1] + A[2] * A[2]));
      }
    gradients.push_back(std::move(g));
    mean_gradients.push_back(std::move(mean));
    offsets.push_back(std::move(x));
    gradient_bound.push_back(bound);
  }



  void
  PlasticPlate::add_points(const FEValues<3>         &fe_values,
                           const std::vector<double> &E,
                           const std::vector<double> &nu)
  {
    double skip = std::numeric_limits<double>::max();
    for (unsigned int q = 0; q < n_points; ++q)
      {
        const double z = fe_values.quadrature_point(q)[2];
        lambda.push_back(HookeLaw::lambda(E[q], nu[q]));
        mu.push_back(HookeLaw::mu(E[q], nu[q]));
        // The ceramic-rich points stay elastic.
        const bool plastic = strength.metal_rich(z);
        yield.push_back(plastic ? strength.yield_strength(z) :
                                  std::numeric_limits<double>::infinity());
        hardening.push_back(plastic ? strength.hardening_modulus(z) : 0.);
        weights.push_back(fe_values.JxW(q));
        position.push_back(fe_values.quadrature_point(q));
        // von Mises = sqrt(3/2) 2 mu |dev eps| <= sqrt(6) mu |grad u|.
        skip = std::min(skip, yield.back() / (std::sqrt(6.) * mu.back()));
      }
    skip_strain.push_back(skip);
  }



  void
  PlasticPlate::begin_increment()
  {
    copy_owned(committed_force, force);
    omega           = 1.;
    first_iteration = true;
    iterations      = 0;
  }



  double
  PlasticPlate::update(const TrilinosWrappers::MPI::Vector &u)
  {
    ++iterations;
    const double *const values = ghosted_values(u);

    new_force = 0.;
    CellResult                           cell;
    std::vector<double>                  cell_u(n_dofs);
    std::vector<types::global_dof_index> cell_dofs(n_dofs);
    Vector<double>                       element_f(n_dofs);
    double                               energy = 0, ratio = 0;
    for (unsigned int c = 0; c < table.size(); ++c)
      {
        for (unsigned int i = 0; i < n_dofs; ++i)
          cell_u[i] = values[local_index[c * n_dofs + i]];
        if (!plastic_cell[c] && can_skip(c, cell_u))
          {
            clear_trial(c);
            continue;
          }
        evaluate_cell(c, cell_u, cell);
        energy += cell.energy;
        ratio = std::max(ratio, cell.ratio);
        if (!cell.plastic)
          continue;
        // Back to the element's DoF order.
        for (unsigned int i = 0; i < n_dofs; ++i)
          {
            const auto [a, s] = plate.get_fe().system_to_component_index(i);
            element_f[i]      = cell.force[3 * s + a];
            cell_dofs[i]      = dofs[c * n_dofs + i];
          }
        plate.get_constraints().distribute_local_to_global(element_f,
                                                           cell_dofs,
                                                           new_force);
      }
    new_force.compress(VectorOperation::add);
    const MPI_Comm comm      = plate.get_mpi_communicator();
    trial_eigenstrain_energy = Utilities::MPI::sum(energy, comm);
    trial_ratio              = Utilities::MPI::max(ratio, comm);

    copy_owned(new_force, residual);
    residual -= force;
    const double change = residual.linfty_norm();
    relax();
    return change;
  }



  const double *
  PlasticPlate::ghosted_values(const TrilinosWrappers::MPI::Vector &u)
  {
    copy_owned(u, u_distributed);
    plate.get_constraints().distribute(u_distributed);
    return importer.import(u_distributed, u_ghosted);
  }



  void
  PlasticPlate::clear_trial(const unsigned int c)
  {
    for (unsigned int q = 0; q < n_points; ++q)
      {
        trial[c * n_points + q]             = PlasticState();
        trial_work[c * n_points + q]        = 0;
        trial_utilization[c * n_points + q] = 0;
      }
  }



  bool
  PlasticPlate::can_skip(const unsigned int         c,
                         const std::vector<double> &cell_u) const
  {
    // grad u(q) = G + sum_s r_s (x) grad N_s(q) for any matrix G, with
    // r_s = u_s - mean u - G (x_s - x_c) (the element reproduces affine
    // fields).  G = the cell's mean gradient takes out the rigid motion
    // and the mean strain, so |dev eps(q)| <= |dev sym G| + max_s |r_s|
    // gradient_bound, and von Mises <= sqrt(6) mu |dev eps|.
    const unsigned int  n_scalar = n_dofs / 3;
    const unsigned int  t        = table[c];
    const double *const mean_g   = mean_gradients[t].data();
    const double *const x        = offsets[t].data();
    double              mean[3] = {}, G[3][3] = {};
    for (unsigned int s = 0; s < n_scalar; ++s)
      for (unsigned int a = 0; a < 3; ++a)
        {
          mean[a] += cell_u[3 * s + a] / n_scalar;
          for (unsigned int d = 0; d < 3; ++d)
            G[a][d] += cell_u[3 * s + a] * mean_g[3 * s + d];
        }
    double R2 = 0;
    for (unsigned int s = 0; s < n_scalar; ++s)
      {
        double r2 = 0;
        for (unsigned int a = 0; a < 3; ++a)
          {
            double r = cell_u[3 * s + a] - mean[a];
            for (unsigned int d = 0; d < 3; ++d)
              r -= G[a][d] * x[3 * s + d];
            r2 += r * r;
          }
        R2 = std::max(R2, r2);
      }
    SymmetricTensor<2, 3> strain;
    for (unsigned int a = 0; a < 3; ++a)
      for (unsigned int d = a; d < 3; ++d)
        strain[a][d] = 0.5 * (G[a][d] + G[d][a]);
    const double bound = deviator(strain).norm() +
                         std::sqrt(R2) * gradient_bound[t] +
                         (prestrain.empty() ? 0. : prestrain_dev[c]);
    // Half the yield strain: max_trial_ratio() is then exact whenever it
    // is above 1/2 (first yield is interpolated from it).
    return bound < 0.5 * skip_strain[c];
  }



  double
  PlasticPlate::utilization_of(const PlasticUpdate &update,
                               const unsigned int   k) const
  {
    // The returned stress over the new yield stress (1 on the yield
    // surface): kept for the VTU's cell data of plastic points.
    return update.state.equivalent_plastic_strain > 0. ?
             std::sqrt(1.5) * deviator(update.stress).norm() /
               (yield[k] +
                hardening[k] * update.state.equivalent_plastic_strain) :
             0.;
  }



  void
  PlasticPlate::evaluate_cell(const unsigned int         c,
                              const std::vector<double> &cell_u,
                              CellResult                &result)
  {
    const unsigned int  n_scalar = n_dofs / 3;
    const double *const grad     = gradients[table[c]].data();
    result.force.assign(n_dofs, 0.);
    result.plastic = false;
    result.energy = result.ratio = 0;
    for (unsigned int q = 0; q < n_points; ++q)
      {
        const unsigned int    k = c * n_points + q;
        SymmetricTensor<2, 3> strain;
        for (unsigned int s = 0; s < n_scalar; ++s)
          {
            const double *const g  = grad + (q * n_scalar + s) * 3;
            const double *const us = cell_u.data() + 3 * s;
            for (unsigned int a = 0; a < 3; ++a)
              for (unsigned int d = a; d < 3; ++d)
                strain[a][d] += 0.5 * (us[a] * g[d] + us[d] * g[a]);
          }
        if (!prestrain.empty())
          strain += prestrain[k]; // the total mechanical strain
        const PlasticState &old    = committed[k];
        const PlasticUpdate update = J2Plasticity::update(
          lambda[k], mu[k], yield[k], hardening[k], strain, old, false);
        trial[k]             = update.state;
        trial_work[k]        = update.plastic_work * weights[k];
        trial_utilization[k] = utilization_of(update, k);
        const double s_trial =
          2. * mu[k] * deviator(strain - old.plastic_strain).norm();
        result.ratio =
          std::max(result.ratio,
                   std::sqrt(1.5) * s_trial /
                     (yield[k] + hardening[k] * old.equivalent_plastic_strain));
        if (update.state.equivalent_plastic_strain == 0.)
          continue;
        result.plastic = true;
        // f_p = int B^T sigma_p, sigma_p = 2 mu eps_p (tr eps_p = 0).
        const SymmetricTensor<2, 3> &eps_p   = update.state.plastic_strain;
        const SymmetricTensor<2, 3>  sigma_p = 2. * mu[k] * eps_p;
        result.energy += 0.5 * (sigma_p * eps_p) * weights[k];
        // The pre-stress's part, -sigma0 : eps_p = -2 mu eps0 : eps_p
        // (tr eps_p = 0).
        if (!prestrain.empty())
          result.energy -= 2. * mu[k] * (prestrain[k] * eps_p) * weights[k];
        for (unsigned int s = 0; s < n_scalar; ++s)
          {
            const double *const g = grad + (q * n_scalar + s) * 3;
            for (unsigned int a = 0; a < 3; ++a)
              result.force[3 * s + a] +=
                (sigma_p[a][0] * g[0] + sigma_p[a][1] * g[1] +
                 sigma_p[a][2] * g[2]) *
                weights[k];
          }
      }
  }



  void
  PlasticPlate::relax()
  {
    // Aitken: omega_k = -omega_{k-1} r_{k-1}.(r_k - r_{k-1}) / |r_k -
    // r_{k-1}|^2.  The initial-stiffness map contracts with real factors
    // in [0, 1), so the factor over-relaxes (it grows as the map slows); it
    // is kept within [1/2, 20].
    if (!first_iteration)
      {
        last_residual -= residual; // d = r_{k-1} - r_k
        const double d2 = last_residual.norm_sqr();
        if (d2 > 0.)
          {
            // r_{k-1}.d = |d|^2 + r_k.d
            const double r_dot = last_residual * residual;
            omega = std::clamp(omega * (d2 + r_dot) / d2, 0.5, 20.);
          }
      }
    first_iteration = false;
    copy_owned(residual, last_residual);
    force.add(omega, residual);
  }



  void
  PlasticPlate::commit()
  {
    double local_work = 0, local_max = 0;
    for (unsigned int c = 0; c < table.size(); ++c)
      {
        bool plastic = false;
        for (unsigned int q = 0; q < n_points; ++q)
          {
            const unsigned int k = c * n_points + q;
            committed[k]         = trial[k];
            utilization[k]       = trial_utilization[k];
            local_work += trial_work[k];
            local_max = std::max(local_max, trial[k].equivalent_plastic_strain);
            plastic   = plastic || trial[k].equivalent_plastic_strain > 0.;
          }
        plastic_cell[c] = plastic;
      }
    const MPI_Comm comm = plate.get_mpi_communicator();
    total_iterations += iterations;
    max_iterations = std::max(max_iterations, iterations);
    work += Utilities::MPI::sum(local_work, comm);
    max_plastic_strain = Utilities::MPI::max(local_max, comm);
    // The force of the accepted state, unrelaxed: the next increment
    // starts from the committed plastic strain's own load.
    copy_owned(new_force, committed_force);
    copy_owned(new_force, force);
  }
} // namespace fgimpact
