#include <deal.II/base/quadrature_lib.h>

#include <fgimpact/material/constitutive_law.h>

#include <algorithm>
#include <string>

namespace fgimpact
{
  namespace
  {
    /// The shifted Legendre polynomials P_0 .. P_degree at x in [0, 1].
    std::vector<double>
    legendre(const unsigned int degree, const double x)
    {
      std::vector<double> P(degree + 1);
      const double        t = 2. * x - 1.;
      P[0]                  = 1.;
      if (degree >= 1)
        P[1] = t;
      for (unsigned int j = 1; j < degree; ++j)
        P[j + 1] = ((2. * j + 1.) * t * P[j] - j * P[j - 1]) / (j + 1.);
      return P;
    }

    /**
     * The L2 projection of the profile over [z0, z0 + hz] onto the
     * polynomials of degree `degree` in z, evaluated at the unit heights
     * `unit_z`: P_h(x) = sum_j a_j P_j(x), a_j = (2j+1) int_0^1 P P_j dx.
     * The integrals use 8-point Gauss rules on 64 equal sub-intervals, so
     * that a boundary layer (z^n, n -> 0+) is integrated to ~1e-6.
     */
    std::vector<IsotropicProperties>
    layer_projection(const FunctionallyGradedMaterial &material,
                     const double                      z0,
                     const double                      hz,
                     const unsigned int                degree,
                     const std::vector<double>        &unit_z)
    {
      const QGauss<1>     gauss(8);
      const unsigned int  n_sub = 64;
      std::vector<double> a_E(degree + 1), a_nu(degree + 1), a_rho(degree + 1);
      for (unsigned int s = 0; s < n_sub; ++s)
        for (unsigned int q = 0; q < gauss.size(); ++q)
          {
            const double              x = (s + gauss.point(q)[0]) / n_sub;
            const double              w = gauss.weight(q) / n_sub;
            const IsotropicProperties p = material.properties(z0 + x * hz);
            const std::vector<double> P = legendre(degree, x);
            for (unsigned int j = 0; j <= degree; ++j)
              {
                a_E[j] += (2. * j + 1.) * w * p.E * P[j];
                a_nu[j] += (2. * j + 1.) * w * p.nu * P[j];
                a_rho[j] += (2. * j + 1.) * w * p.rho * P[j];
              }
          }
      std::vector<IsotropicProperties> values;
      for (const double x : unit_z)
        {
          const std::vector<double> P = legendre(degree, x);
          IsotropicProperties       v{0., 0., 0.};
          for (unsigned int j = 0; j <= degree; ++j)
            {
              v.E += a_E[j] * P[j];
              v.nu += a_nu[j] * P[j];
              v.rho += a_rho[j] * P[j];
            }
          // A projection is not monotone: a jump inside the element can
          // overshoot out of the admissible range.
          AssertThrow(v.E > 0. && v.rho > 0. && v.nu > -1. && v.nu < 0.5,
                      ExcMessage(
                        "Material/Graded nodal values = layer average: the "
                        "projected profile is not admissible in the element "
                        "layer z = " +
                        std::to_string(z0) + " .. " + std::to_string(z0 + hz) +
                        " m; use Material/Property mode = pointwise or more "
                        "elements in z."));
          values.push_back(v);
        }
      return values;
    }
  } // namespace



  std::pair<double, unsigned int>
  sampled_layer_error(const FunctionallyGradedMaterial &material,
                      const double                      h,
                      const unsigned int                n_layers,
                      const unsigned int                degree)
  {
    const QGauss<1>                 gauss(8);
    const unsigned int              n_sub = 64; // as layer_projection()
    std::pair<double, unsigned int> worst{0., 0u};
    for (unsigned int l = 0; l < n_layers; ++l)
      {
        const double z0 = h * l / n_layers, hz = h / n_layers;
        double       exact = 0;
        for (unsigned int s = 0; s < n_sub; ++s)
          for (unsigned int q = 0; q < gauss.size(); ++q)
            exact +=
              gauss.weight(q) / n_sub *
              material.properties(z0 + (s + gauss.point(q)[0]) / n_sub * hz).E;
        const double E0 = material.properties(z0).E,
                     E1 = material.properties(z0 + hz).E;
        const double sampled =
          degree == 1 ?
            0.5 * (E0 + E1) :
            (E0 + 4. * material.properties(z0 + 0.5 * hz).E + E1) / 6.;
        const double error = std::abs(sampled - exact) / exact;
        if (error > worst.first)
          worst = {error, l};
      }
    return worst;
  }



  PropertyInterpolator::PropertyInterpolator(
    const FiniteElement<3>           &scalar_fe,
    const std::vector<Point<3>>      &unit_points,
    const FunctionallyGradedMaterial &material)
    : scalar_fe(scalar_fe)
    , material(material)
    , cache(std::make_shared<Cache>())
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



  const std::vector<IsotropicProperties> &
  PropertyInterpolator::nodal_values(const double z0, const double hz) const
  {
    std::lock_guard<std::mutex> lock(cache->mutex);
    auto                       &values = cache->layers[{z0, hz}];
    if (!values.empty())
      return values;
    if (material.get_parameters().graded_nodal_values ==
        GradedNodalValues::sampled)
      {
        for (const double z : unit_support_z)
          values.push_back(material.properties(z0 + z * hz));
        return values;
      }
    values = layer_projection(
      material, z0, hz, scalar_fe.tensor_degree(), unit_support_z);
    return values;
  }



  void
  PropertyInterpolator::values(
    const typename Triangulation<3>::cell_iterator &cell,
    std::vector<double>                            &E,
    std::vector<double>                            &nu,
    std::vector<double>                            &rho) const
  {
    const unsigned int n_q = shape_values.empty() ? 0 : shape_values[0].size();
    E.resize(n_q);
    nu.resize(n_q);
    rho.resize(n_q);
    // With a constant nu, nu is used exactly (no interpolation round-off).
    const bool constant_nu = material.constant_poissons_ratio();

    // Cells are axis-aligned bricks: vertex 0 is the lowest, vertex 7 the
    // highest corner.
    const double z0 = cell->vertex(0)[2];
    const double hz = cell->vertex(7)[2] - z0;

    if (material.get_parameters().property_mode == PropertyMode::pointwise)
      {
        for (unsigned int q = 0; q < n_q; ++q)
          {
            const IsotropicProperties p =
              material.properties(z0 + unit_point_z[q] * hz);
            E[q]   = p.E;
            nu[q]  = p.nu;
            rho[q] = p.rho;
          }
        return;
      }

    if (material.get_parameters().property_mode == PropertyMode::homogeneous)
      {
        const IsotropicProperties p = material.properties(z0 + 0.5 * hz);
        std::fill(E.begin(), E.end(), p.E);
        std::fill(nu.begin(), nu.end(), p.nu);
        std::fill(rho.begin(), rho.end(), p.rho);
        return;
      }

    // Graded element, Eq. 3.3: P(q) = sum_k N_k(q) P_k.
    const std::vector<IsotropicProperties> &nodal = nodal_values(z0, hz);
    std::fill(E.begin(), E.end(), 0.);
    std::fill(nu.begin(), nu.end(), constant_nu ? nodal[0].nu : 0.);
    std::fill(rho.begin(), rho.end(), 0.);
    for (unsigned int k = 0; k < nodal.size(); ++k)
      for (unsigned int q = 0; q < n_q; ++q)
        {
          E[q] += shape_values[k][q] * nodal[k].E;
          rho[q] += shape_values[k][q] * nodal[k].rho;
          if (!constant_nu)
            nu[q] += shape_values[k][q] * nodal[k].nu;
        }
  }



  IsotropicProperties
  PropertyInterpolator::value_at(
    const typename Triangulation<3>::cell_iterator &cell,
    const Point<3>                                 &p) const
  {
    const double z0 = cell->vertex(0)[2];
    const double hz = cell->vertex(7)[2] - z0;
    switch (material.get_parameters().property_mode)
      {
        case PropertyMode::pointwise:
          return material.properties(p[2]);
        case PropertyMode::homogeneous:
          return material.properties(z0 + 0.5 * hz);
        case PropertyMode::graded:
          break;
      }
    // Eq. 3.3 at the unit point of p (the brick's affine map).
    Point<3> unit;
    for (unsigned int d = 0; d < 3; ++d)
      unit[d] =
        (p[d] - cell->vertex(0)[d]) / (cell->vertex(7)[d] - cell->vertex(0)[d]);
    const std::vector<IsotropicProperties> &nodal = nodal_values(z0, hz);
    IsotropicProperties                     v{0., 0., 0.};
    for (unsigned int k = 0; k < nodal.size(); ++k)
      {
        const double N = scalar_fe.shape_value(k, unit);
        v.E += N * nodal[k].E;
        v.nu += N * nodal[k].nu;
        v.rho += N * nodal[k].rho;
      }
    if (material.constant_poissons_ratio())
      v.nu = nodal[0].nu;
    return v;
  }
} // namespace fgimpact
