// The plastic state at points and per cell, for the outputs
// (plastic_plate.h): what the VTU, the probes and the validity report read;
// and the state's checkpoint section (save(), load()).

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <fgimpact/plate/plastic_plate.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace fgimpact
{
  void
  PlasticPlate::setup_interpolation(const Quadrature<3> &quadrature)
  {
    // The 1D Gauss points, and each 3D point's index among them per
    // coordinate (QGauss<3> is their tensor product).
    const QGauss<1> gauss(plate.get_fe().degree + 1);
    for (const auto &p : gauss.get_points())
      gauss_1d.push_back(p[0]);
    for (unsigned int q = 0; q < quadrature.size(); ++q)
      {
        std::array<unsigned int, 3> index{};
        for (unsigned int d = 0; d < 3; ++d)
          for (unsigned int i = 0; i < gauss_1d.size(); ++i)
            if (std::abs(quadrature.point(q)[d] - gauss_1d[i]) < 1e-12)
              index[d] = i;
        gauss_index.push_back(index);
      }
  }



  Vector<float>
  PlasticPlate::cell_plastic_strain() const
  {
    // DataOut's size: this rank's triangulation (ghost and artificial
    // cells included), not the global count.
    Vector<float> result(
      plate.get_dof_handler().get_triangulation().n_active_cells());
    for (unsigned int c = 0; c < table.size(); ++c)
      for (unsigned int q = 0; q < n_points; ++q)
        result[active_index[c]] = std::max<float>(
          result[active_index[c]],
          committed[c * n_points + q].equivalent_plastic_strain);
    return result;
  }



  Vector<float>
  PlasticPlate::cell_yield_utilization() const
  {
    Vector<float> result(
      plate.get_dof_handler().get_triangulation().n_active_cells());
    for (unsigned int c = 0; c < table.size(); ++c)
      if (plastic_cell[c])
        for (unsigned int q = 0; q < n_points; ++q)
          {
            const unsigned int k = c * n_points + q;
            result[active_index[c]] =
              std::max<float>(result[active_index[c]], utilization[k]);
          }
    return result;
  }



  bool
  PlasticPlate::holds_plastic_strain(const unsigned int active_cell_index) const
  {
    const int c = active_cell_index < cell_of_active.size() ?
                    cell_of_active[active_cell_index] :
                    -1;
    return c >= 0 && plastic_cell[c];
  }



  PlasticState
  PlasticPlate::plastic_state(const unsigned int active_cell_index,
                              const Point<3>    &unit_point) const
  {
    PlasticState state;
    if (!holds_plastic_strain(active_cell_index))
      return state;
    const unsigned int c = cell_of_active[active_cell_index];
    // The 1D Lagrange polynomials through the Gauss points, at each
    // coordinate of the point.
    const unsigned int                 n = gauss_1d.size();
    std::array<std::vector<double>, 3> L;
    for (unsigned int d = 0; d < 3; ++d)
      for (unsigned int i = 0; i < n; ++i)
        {
          double l = 1;
          for (unsigned int j = 0; j < n; ++j)
            if (j != i)
              l *= (unit_point[d] - gauss_1d[j]) / (gauss_1d[i] - gauss_1d[j]);
          L[d].push_back(l);
        }
    for (unsigned int q = 0; q < n_points; ++q)
      {
        const auto  &i     = gauss_index[q];
        const double w     = L[0][i[0]] * L[1][i[1]] * L[2][i[2]];
        const auto  &point = committed[c * n_points + q];
        state.plastic_strain += w * point.plastic_strain;
        state.equivalent_plastic_strain += w * point.equivalent_plastic_strain;
      }
    // An extrapolation can undershoot; the equivalent strain is >= 0.
    state.equivalent_plastic_strain =
      std::max(state.equivalent_plastic_strain, 0.);
    return state;
  }



  std::array<double, 2>
  PlasticPlate::plastic_zone_extent(const Point<3> &centre,
                                    const double    top) const
  {
    double depth = 0, radius = 0;
    for (unsigned int k = 0; k < committed.size(); ++k)
      if (committed[k].equivalent_plastic_strain > 0.)
        {
          const Point<3> &x = position[k];
          depth             = std::max(depth, top - x[2]);
          radius =
            std::max(radius, std::hypot(x[0] - centre[0], x[1] - centre[1]));
        }
    const MPI_Comm comm = plate.get_mpi_communicator();
    return {
      {Utilities::MPI::max(depth, comm), Utilities::MPI::max(radius, comm)}};
  }



  double
  PlasticPlate::yield_stress(const double z,
                             const double equivalent_plastic_strain) const
  {
    if (!strength.metal_rich(z))
      return std::numeric_limits<double>::infinity();
    return strength.yield_strength(z) +
           strength.hardening_modulus(z) * equivalent_plastic_strain;
  }



  void
  PlasticPlate::save(CheckpointWriter &out) const
  {
    std::vector<double> state;
    state.reserve(7 * committed.size());
    for (const auto &point : committed)
      {
        for (unsigned int i = 0;
             i < SymmetricTensor<2, 3>::n_independent_components;
             ++i)
          state.push_back(point.plastic_strain.access_raw_entry(i));
        state.push_back(point.equivalent_plastic_strain);
      }
    out.put(state);
    out.put(committed_force);
    out.put(work);
    out.put(max_plastic_strain);
    out.put(total_iterations);
    out.put(max_iterations);
  }



  void
  PlasticPlate::load(CheckpointReader &in)
  {
    std::vector<double> state;
    in.get(state);
    AssertThrow(state.size() == 7 * committed.size(),
                ExcMessage("the checkpoint's plastic state does not match "
                           "this mesh."));
    for (unsigned int k = 0; k < committed.size(); ++k)
      {
        for (unsigned int i = 0; i < 6; ++i)
          committed[k].plastic_strain.access_raw_entry(i) = state[7 * k + i];
        committed[k].equivalent_plastic_strain = state[7 * k + 6];
      }
    trial = committed;
    for (unsigned int c = 0; c < table.size(); ++c)
      {
        bool plastic = false;
        for (unsigned int q = 0; q < n_points; ++q)
          plastic = plastic ||
                    committed[c * n_points + q].equivalent_plastic_strain > 0.;
        plastic_cell[c] = plastic;
      }
    in.get(committed_force);
    in.get(work);
    in.get(max_plastic_strain);
    in.get(total_iterations);
    in.get(max_iterations);
    copy_owned(committed_force, force);
    copy_owned(committed_force, new_force);
  }
} // namespace fgimpact
