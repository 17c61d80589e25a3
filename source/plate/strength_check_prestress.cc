#include <fgimpact/plate/strength_check.h>

#include <algorithm>
#include <cmath>

namespace fgimpact
{
  const double *
  StrengthCheck::gather(const TrilinosWrappers::MPI::Vector &u)
  {
    return importer.import(u, u_ghosted);
  }



  void
  StrengthCheck::set_prestress(const TrilinosWrappers::MPI::Vector &u_th,
                               const TemperatureProfile            &temperature)
  {
    TrilinosWrappers::MPI::Vector owned;
    plate.initialize_vector(owned);
    owned                      = u_th;
    const double *const values = gather(owned);
    const unsigned int  n_dofs = 3 * n_scalar;
    std::vector<double> cell_u(n_dofs);
    prestrain.assign(table.size() * n_points, {});
    prestrain_dev.assign(table.size(), 0.);
    prestrain_trace.assign(table.size(), 0.);
    prestrain_norm.assign(table.size(), 0.);
    for (unsigned int c = 0; c < table.size(); ++c)
      {
        for (unsigned int i = 0; i < n_dofs; ++i)
          cell_u[i] = values[local_index[c * n_dofs + i]];
        const auto &m     = mean_divergences[table[c]];
        double      theta = 0; // B-bar: the cell's mean dilatation
        for (unsigned int i = 0; i < m.size(); ++i)
          theta += m[i] * cell_u[i];
        for (unsigned int q = 0; q < n_points; ++q)
          {
            const unsigned int k = c * n_points + q;
            double             G[3][3];
            displacement_gradient(
              c, q, cell_u, m.empty() ? nullptr : &theta, G);
            const double e  = temperature.thermal_strain(points[k][2]);
            auto        &p  = prestrain[k];
            p               = {{G[0][0] - e,
                                G[1][1] - e,
                                G[2][2] - e,
                                0.5 * (G[0][1] + G[1][0]),
                                0.5 * (G[0][2] + G[2][0]),
                                0.5 * (G[1][2] + G[2][1])}};
            const double tr = p[0] + p[1] + p[2];
            double       d2 = 2. * (p[3] * p[3] + p[4] * p[4] + p[5] * p[5]);
            for (unsigned int a = 0; a < 3; ++a)
              d2 += std::pow(p[a] - tr / 3., 2);
            prestrain_dev[c]   = std::max(prestrain_dev[c], std::sqrt(d2));
            prestrain_trace[c] = std::max(prestrain_trace[c], std::abs(tr));
            prestrain_norm[c] =
              std::max(prestrain_norm[c], std::sqrt(d2 + tr * tr / 3.));
          }
      }
  }



  void
  StrengthCheck::add_prestrain(const unsigned int k, double G[3][3]) const
  {
    // The symmetric part of G takes eps0 (its skew part is not read).
    const auto &p = prestrain[k];
    G[0][0] += p[0];
    G[1][1] += p[1];
    G[2][2] += p[2];
    G[0][1] += p[3], G[1][0] += p[3];
    G[0][2] += p[4], G[2][0] += p[4];
    G[1][2] += p[5], G[2][1] += p[5];
  }
} // namespace fgimpact
