#include <fgimpact/constitutive_law.h>

#include <algorithm>

namespace fgimpact
{
  PropertyInterpolator::PropertyInterpolator(
    const FiniteElement<3>           &scalar_fe,
    const std::vector<Point<3>>      &unit_points,
    const FunctionallyGradedMaterial &material)
    : scalar_fe(scalar_fe)
    , material(material)
  {
    for (const auto &p : unit_points)
      unit_point_z.push_back(p[2]);
    const auto &support = scalar_fe.get_unit_support_points();
    for (const auto &p : support)
      unit_support_z.push_back(p[2]);
    shape_values.resize(support.size(),
                        std::vector<double>(unit_points.size()));
    for (unsigned int k = 0; k < support.size(); ++k)
      for (unsigned int q = 0; q < unit_points.size(); ++q)
        shape_values[k][q] = scalar_fe.shape_value(k, unit_points[q]);
  }



  void
  PropertyInterpolator::values(
    const typename Triangulation<3>::cell_iterator &cell,
    std::vector<double>                            &E,
    std::vector<double>                            &rho) const
  {
    const unsigned int n_q = shape_values.empty() ? 0 : shape_values[0].size();
    E.resize(n_q);
    rho.resize(n_q);

    // Cells are axis-aligned bricks: vertex 0 is the lowest, vertex 7 the
    // highest corner.
    const double z0 = cell->vertex(0)[2];
    const double hz = cell->vertex(7)[2] - z0;

    if (material.get_parameters().property_mode == PropertyMode::pointwise)
      {
        for (unsigned int q = 0; q < n_q; ++q)
          {
            const double z = z0 + unit_point_z[q] * hz;
            E[q]           = material.youngs_modulus(z);
            rho[q]         = material.density(z);
          }
        return;
      }

    if (material.get_parameters().property_mode == PropertyMode::homogeneous)
      {
        const double zc = z0 + 0.5 * hz;
        std::fill(E.begin(), E.end(), material.youngs_modulus(zc));
        std::fill(rho.begin(), rho.end(), material.density(zc));
        return;
      }

    // Graded element, Eq. 3.3: P(q) = sum_k N_k(q) P(z_k).
    std::fill(E.begin(), E.end(), 0.);
    std::fill(rho.begin(), rho.end(), 0.);
    for (unsigned int k = 0; k < unit_support_z.size(); ++k)
      {
        const double z     = z0 + unit_support_z[k] * hz;
        const double E_k   = material.youngs_modulus(z);
        const double rho_k = material.density(z);
        for (unsigned int q = 0; q < n_q; ++q)
          {
            E[q] += shape_values[k][q] * E_k;
            rho[q] += shape_values[k][q] * rho_k;
          }
      }
  }



  std::pair<double, double>
  PropertyInterpolator::value_at(
    const typename Triangulation<3>::cell_iterator &cell,
    const Point<3>                                 &p) const
  {
    const double z0 = cell->vertex(0)[2];
    const double hz = cell->vertex(7)[2] - z0;
    switch (material.get_parameters().property_mode)
      {
        case PropertyMode::pointwise:
          return {material.youngs_modulus(p[2]), material.density(p[2])};
        case PropertyMode::homogeneous:
          return {material.youngs_modulus(z0 + 0.5 * hz),
                  material.density(z0 + 0.5 * hz)};
        case PropertyMode::graded:
          break;
      }
    // Eq. 3.3 at the unit point of p (the brick's affine map).
    Point<3> unit;
    for (unsigned int d = 0; d < 3; ++d)
      unit[d] =
        (p[d] - cell->vertex(0)[d]) / (cell->vertex(7)[d] - cell->vertex(0)[d]);
    double E = 0, rho = 0;
    for (unsigned int k = 0; k < unit_support_z.size(); ++k)
      {
        const double z = z0 + unit_support_z[k] * hz;
        const double N = scalar_fe.shape_value(k, unit);
        E += N * material.youngs_modulus(z);
        rho += N * material.density(z);
      }
    return {E, rho};
  }
} // namespace fgimpact
