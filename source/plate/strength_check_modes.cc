// StrengthCheck with incompatible modes (strength_check.h): each checked
// cell's strain includes its modes', as the stiffness has it.

#include <fgimpact/plate/incompatible_modes.h>
#include <fgimpact/plate/strength_check.h>

#include <cmath>

namespace fgimpact
{
  void
  StrengthCheck::add_mode_table(const DoFHandler<3>::active_cell_iterator &cell,
                                const std::array<double, 3> &extent)
  {
    // H depends on the cell's extents and on E(z), nu(z) in it: one
    // table per extent and height of the centre (m, to 1e-12 of the
    // extent: the layers of a box mesh repeat exactly).
    const double z = std::round(cell->center()[2] / (1e-12 * extent[2]));
    const auto [it, added] =
      mode_keys.emplace(std::make_pair(extent, z), mode_tables.size());
    if (added)
      {
        const FullMatrix<double> H  = plate.mode_amplitudes(cell);
        const auto              &fe = plate.get_fe();
        mode_tables.emplace_back(IncompatibleModes::n_modes, H.n());
        for (unsigned int i = 0; i < H.n(); ++i)
          {
            const auto [component, s] = fe.system_to_component_index(i);
            for (unsigned int a = 0; a < IncompatibleModes::n_modes; ++a)
              mode_tables.back()(a, s * 3 + component) = H(a, i);
          }
      }
    mode_table.push_back(it->second);
  }



  bool
  StrengthCheck::mode_amplitudes(const unsigned int         c,
                                 const std::vector<double> &cell_u,
                                 std::array<double, 9>     &alpha) const
  {
    if (mode_tables.empty())
      return false;
    const FullMatrix<double> &H = mode_tables[mode_table[c]];
    for (unsigned int a = 0; a < IncompatibleModes::n_modes; ++a)
      {
        alpha[a] = 0.;
        for (unsigned int j = 0; j < H.n(); ++j)
          alpha[a] += H(a, j) * cell_u[j];
      }
    return true;
  }



  void
  StrengthCheck::add_mode_gradient(const unsigned int           c,
                                   const unsigned int           q,
                                   const std::array<double, 9> &alpha,
                                   double                       G[3][3]) const
  {
    // N_d = 1 - xi_d^2, xi = 2 xhat - 1: dN_d/dx_d = -4 xi_d / h_d.
    const std::array<double, 3> &h = extents[table[c]];
    for (unsigned int a = 0; a < 3; ++a)
      for (unsigned int d = 0; d < 3; ++d)
        G[a][d] +=
          alpha[3 * a + d] * (-4. * (2. * unit_support[q][d] - 1.)) / h[d];
  }
} // namespace fgimpact
