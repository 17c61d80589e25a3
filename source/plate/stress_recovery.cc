#include <deal.II/base/quadrature.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_values.h>

#include <fgimpact/base/checkpoint.h>
#include <fgimpact/material/constitutive_law.h>
#include <fgimpact/plate/stress_recovery.h>

#include <algorithm>
#include <cmath>

namespace fgimpact
{
  bool
  odd_under_reflection(const unsigned int s, const unsigned int planes)
  {
    for (unsigned int d = 0; d < 2; ++d)
      if ((planes & (1u << d)) &&
          ((stress_component[s][0] == d) != (stress_component[s][1] == d)))
        return true;
    return false;
  }



  std::map<types::global_dof_index, unsigned int>
  dofs_on_cut_planes(const PlateGeometry &geometry,
                     const DoFHandler<3> &scalar_dofs)
  {
    std::map<types::global_dof_index, unsigned int> planes;
    if (!geometry.is_cut(0) && !geometry.is_cut(1))
      return planes;
    // The cut face x = a/2 has boundary id 1, y = b/2 id 3 (colorized).
    std::vector<types::global_dof_index> dofs(
      scalar_dofs.get_fe().n_dofs_per_face());
    for (const auto &cell : scalar_dofs.active_cell_iterators())
      if (cell->is_locally_owned() || cell->is_ghost())
        for (const auto &face : cell->face_iterators())
          for (unsigned int d = 0; d < 2; ++d)
            if (geometry.is_cut(d) && face->at_boundary() &&
                face->boundary_id() == 2 * d + 1)
              {
                face->get_dof_indices(dofs);
                for (const auto dof : dofs)
                  planes[dof] |= 1u << d;
              }
    return planes;
  }



  StressRecovery::StressRecovery(const PlateModel &plate)
    : plate(plate)
    , dof_handler(plate.get_dof_handler().get_triangulation())
  {
    dof_handler.distribute_dofs(plate.get_fe().base_element(0));
    owned = dof_handler.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
    const MPI_Comm comm = plate.get_mpi_communicator();

    for (auto &v : sums)
      v.reinit(owned, relevant, comm, /*vector_writable=*/true);
    for (unsigned int f = 0; f < n_fields; ++f)
      {
        owned_values[f].reinit(owned, comm);
        ghosted[f].reinit(owned, relevant, comm);
      }

    // How many locally owned cells, on any rank, share each scalar DoF.
    TrilinosWrappers::MPI::Vector count;
    count.reinit(owned, relevant, comm, /*vector_writable=*/true);
    std::vector<types::global_dof_index> dofs(
      dof_handler.get_fe().n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(dofs);
          for (const auto dof : dofs)
            count(dof) += 1.;
        }
    count.compress(VectorOperation::add);
    inverse_count.reinit(owned, comm);
    for (const auto dof : owned)
      inverse_count(dof) = 1. / count(dof);
    cut_planes = dofs_on_cut_planes(plate.get_geometry(), dof_handler);
    hanging    = scalar_hanging_constraints(dof_handler);
  }



  void
  StressRecovery::set_plasticity(const PlasticPlate &plastic)
  {
    plasticity          = &plastic;
    const MPI_Comm comm = plate.get_mpi_communicator();
    std::map<types::global_dof_index, Point<3>> support;
    DoFTools::map_dofs_to_support_points(plate.get_mapping(),
                                         dof_handler,
                                         support);
    support_z.assign(owned.n_elements(), 0.);
    for (const auto &[dof, x] : support)
      if (owned.is_element(dof))
        support_z[owned.index_within_set(dof)] = x[2];
    plastic_sum.reinit(owned, relevant, comm, /*vector_writable=*/true);
    for (unsigned int f = 0; f < 2; ++f)
      {
        plastic_owned[f].reinit(owned, comm);
        plastic_ghosted[f].reinit(owned, relevant, comm);
      }
  }



  SymmetricTensor<2, 3>
  StressRecovery::carried_stress(
    const DoFHandler<3>::active_cell_iterator &cell,
    const Point<3>                            &unit_point,
    const double                               z,
    const double                               E,
    const double                               nu,
    const SymmetricTensor<2, 3>               &eps,
    double                                    &eps_bar_sum) const
  {
    const PlasticState state =
      plasticity->plastic_state(cell->active_cell_index(), unit_point);
    eps_bar_sum += state.equivalent_plastic_strain;
    return J2Plasticity::admissible_stress(
      HookeLaw::stress(E, nu, eps - state.plastic_strain),
      plasticity->yield_stress(z, state.equivalent_plastic_strain));
  }



  AffineConstraints<double>
  scalar_hanging_constraints(const DoFHandler<3> &dof_handler)
  {
    IndexSet relevant;
    DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
    AffineConstraints<double> constraints;
    constraints.reinit(relevant);
    DoFTools::make_hanging_node_constraints(dof_handler, constraints);
    constraints.close();
    return constraints;
  }



  std::string
  StressRecovery::name(const Field f)
  {
    static const char *const names[n_fields] = {"sigma_xx_MPa",
                                                "sigma_yy_MPa",
                                                "sigma_zz_MPa",
                                                "sigma_xy_MPa",
                                                "sigma_xz_MPa",
                                                "sigma_yz_MPa",
                                                "von_mises_MPa",
                                                "sigma_1_MPa",
                                                "sigma_2_MPa",
                                                "sigma_3_MPa",
                                                "strain_xx",
                                                "strain_yy",
                                                "strain_zz",
                                                "strain_xy",
                                                "strain_xz",
                                                "strain_yz",
                                                "peak_von_mises_MPa",
                                                "peak_abs_sigma_zz_MPa"};
    return names[f];
  }



  SymmetricTensor<2, 3>
  StressRecovery::stress(const types::global_dof_index dof) const
  {
    SymmetricTensor<2, 3> sigma;
    for (unsigned int s = 0; s < 6; ++s)
      sigma[stress_component[s][0]][stress_component[s][1]] =
        ghosted[s](dof) * 1e6;
    return sigma;
  }



  void
  StressRecovery::add_to_sums(const types::global_dof_index dof,
                              const SymmetricTensor<2, 3>  &sigma,
                              const SymmetricTensor<2, 3>  &eps,
                              const double                  eps_bar)
  {
    if (plasticity)
      plastic_sum(dof) += eps_bar;
    for (unsigned int s = 0; s < 6; ++s)
      {
        const unsigned int a = stress_component[s][0],
                           b = stress_component[s][1];
        sums[s](dof) += sigma[a][b] * 1e-6;
        sums[6 + s](dof) += eps[a][b];
      }
  }



  void
  StressRecovery::accumulate_cell_values(
    const TrilinosWrappers::MPI::Vector &u_ghosted)
  {
    const FiniteElement<3> &scalar_fe = dof_handler.get_fe();
    // The strain and stress of every cell at its scalar support points,
    // with E from the PropertyInterpolator and sigma from the HookeLaw of
    // the assembly and the probes.
    const Quadrature<3>  points(scalar_fe.get_unit_support_points());
    FEValues<3>          fe_values(plate.get_mapping(),
                          plate.get_fe(),
                          points,
                          update_gradients | update_quadrature_points);
    PropertyInterpolator properties(scalar_fe,
                                    points.get_points(),
                                    plate.get_material());
    const FEValuesExtractors::Vector   displacement(0);
    std::vector<SymmetricTensor<2, 3>> eps(points.size()), eps0(points.size());
    std::vector<double>                E, nu, rho;
    std::vector<types::global_dof_index> dofs(scalar_fe.n_dofs_per_cell());
    for (auto &v : sums)
      v = 0.;
    if (plasticity)
      plastic_sum = 0.;
    for (const auto &cell : plate.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          fe_values[displacement].get_function_symmetric_gradients(u_ghosted,
                                                                   eps);
          plate.apply_mean_dilatation(cell, u_ghosted, eps); // B-bar
          plate.add_mode_strains(cell, points.get_points(), u_ghosted, eps);
          if (initial) // the total stress; the strain stays the analysis's
            initial->strain(fe_values, cell, eps0);
          properties.values(cell, E, nu, rho);
          const DoFHandler<3>::active_cell_iterator scalar_cell(
            &dof_handler.get_triangulation(),
            cell->level(),
            cell->index(),
            &dof_handler);
          scalar_cell->get_dof_indices(dofs);
          for (unsigned int q = 0; q < points.size(); ++q)
            {
              double                      eps_bar = 0;
              const SymmetricTensor<2, 3> sigma =
                plasticity ? carried_stress(cell,
                                            points.point(q),
                                            fe_values.quadrature_point(q)[2],
                                            E[q],
                                            nu[q],
                                            eps[q] + eps0[q],
                                            eps_bar) :
                             HookeLaw::stress(E[q], nu[q], eps[q] + eps0[q]);
              add_to_sums(dofs[q], sigma, eps[q], eps_bar);
            }
        }
    for (unsigned int s = 0; s < 12; ++s)
      sums[s].compress(VectorOperation::add);
    if (plasticity)
      plastic_sum.compress(VectorOperation::add);
  }



  void
  StressRecovery::average_and_derive()
  {
    for (const auto dof : owned)
      {
        const double w      = inverse_count(dof);
        const auto   it     = cut_planes.find(dof);
        const auto   planes = (it == cut_planes.end() ? 0u : it->second);
        SymmetricTensor<2, 3> sigma;
        for (unsigned int s = 0; s < 6; ++s)
          {
            // On a cut plane the whole plate's average also holds the
            // mirrored cells, whose shear components normal to the plane
            // have the opposite sign: they average to zero there.
            const double odd   = odd_under_reflection(s, planes) ? 0. : 1.;
            const double value = odd * sums[s](dof) * w;
            owned_values[stress_xx + s](dof) = value;
            owned_values[strain_xx + s](dof) = odd * sums[6 + s](dof) * w;
            sigma[stress_component[s][0]][stress_component[s][1]] = value;
          }
        const SymmetricTensor<2, 3> s  = deviator(sigma);
        const double                vm = std::sqrt(1.5 * (s * s));
        const auto principal           = eigenvalues(sigma); // descending
        owned_values[von_mises](dof)   = vm;
        for (unsigned int k = 0; k < 3; ++k)
          owned_values[principal_1 + k](dof) = principal[k];

        if (plasticity)
          {
            const double eps_bar = plastic_sum(dof) * w;
            // The support point's height (m) gives its yield strength.
            const double sigma_y =
              plasticity->yield_stress(support_z[owned.index_within_set(dof)],
                                       eps_bar);
            plastic_owned[0](dof) = eps_bar;
            plastic_owned[1](dof) =
              std::isfinite(sigma_y) ? sigma_y * 1e-6 : 0.;
          }
        const double abs_zz = std::abs(sigma[2][2]);
        owned_values[peak_von_mises](dof) =
          n_recovered == 0 ?
            vm :
            std::max<double>(owned_values[peak_von_mises](dof), vm);
        owned_values[peak_abs_stress_zz](dof) =
          n_recovered == 0 ?
            abs_zz :
            std::max<double>(owned_values[peak_abs_stress_zz](dof), abs_zz);
      }
  }



  void
  StressRecovery::recover(const TrilinosWrappers::MPI::Vector &u_ghosted)
  {
    accumulate_cell_values(u_ghosted);
    average_and_derive();
    // A hanging node's average holds only its fine cells: its value is
    // its parents' interpolation instead, as for the displacement, so that
    // the coarse and the fine cells show the same field there.
    for (unsigned int f = 0; f < n_fields; ++f)
      {
        hanging.distribute(owned_values[f]);
        ghosted[f] = owned_values[f];
      }
    if (plasticity)
      for (unsigned int f = 0; f < 2; ++f)
        {
          hanging.distribute(plastic_owned[f]);
          plastic_ghosted[f] = plastic_owned[f];
        }
    ++n_recovered;
  }



  void
  StressRecovery::save_peaks(CheckpointWriter &out) const
  {
    out.put(n_recovered);
    out.put(owned_values[peak_von_mises]);
    out.put(owned_values[peak_abs_stress_zz]);
  }



  void
  StressRecovery::load_peaks(CheckpointReader &in)
  {
    in.get(n_recovered);
    for (const auto f : {peak_von_mises, peak_abs_stress_zz})
      {
        in.get(owned_values[f]);
        ghosted[f] = owned_values[f];
      }
  }
} // namespace fgimpact
