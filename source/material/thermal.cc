#include <deal.II/base/quadrature_lib.h>

#include <fgimpact/base/parameter_table.h>
#include <fgimpact/material/thermal.h>

#include <algorithm>
#include <cmath>

namespace fgimpact
{
  const SelectionTable<TemperatureField> &
  temperature_field_names()
  {
    static const SelectionTable<TemperatureField> names = {
      {"none", TemperatureField::none},
      {"uniform", TemperatureField::uniform},
      {"linear", TemperatureField::linear},
      {"conduction", TemperatureField::conduction}};
    return names;
  }



  namespace
  {
    /// The entries of Thermal.
    const ParameterTable<ThermalParameters> &
    thermal_table()
    {
      using P                              = ThermalParameters;
      static const ParameterTable<P> table = [] {
        ParameterTable<P> t;
        t.add("Temperature field",
              &P::field,
              temperature_field_names(),
              "The temperature through the thickness, whose thermal strain "
              "alpha(z) (T(z) - Reference temperature) a static thermal step "
              "turns into the initial displacement and stress of the analysis. "
              "none: no thermal step (the plate is stress free). uniform: T = "
              "Reference temperature + Temperature change. linear: T linear in "
              "z from Bottom temperature (z = 0, the ceramic face) to Top "
              "temperature (z = h, the metal face). conduction: steady "
              "conduction through the graded conductivity k(z) between the "
              "same two face temperatures (doc/thermal.md).");
        t.add("Reference temperature",
              &P::reference_temperature,
              Patterns::Double(1e-3, 1e5),
              "The stress-free temperature T_ref. Unit: K.");
        t.add("Temperature change",
              &P::temperature_change,
              Patterns::Double(-1e5, 1e5),
              "Temperature field = uniform: Delta T = T - T_ref, the same "
              "at every point. Unit: K.");
        t.add("Top temperature",
              &P::top_temperature,
              Patterns::Double(1e-3, 1e5),
              "Temperature field = linear or conduction: T at the top face "
              "z = h (the metal face). Unit: K.");
        t.add("Bottom temperature",
              &P::bottom_temperature,
              Patterns::Double(1e-3, 1e5),
              "Temperature field = linear or conduction: T at the bottom "
              "face z = 0 (the ceramic face). Unit: K.");
        t.add("Geometric stiffness",
              &P::geometric_stiffness,
              Patterns::Bool(),
              "Add the initial-stress stiffness of the thermal pre-stress, "
              "K_sigma = int grad(N)^T sigma0 grad(N) dV, to the plate's "
              "stiffness in every analysis (impact, static, modal): a "
              "compressive pre-stress lowers the bending stiffness, the "
              "frequencies and the impact force. Also solves for the "
              "thermal buckling factor, the multiple of T - T_ref at which "
              "K + factor K_sigma turns singular (summary.txt: "
              "thermal_buckling_factor, thermal_buckling_temperature_change_K)"
              "; a temperature field at or beyond it is refused. Without "
              "it the pre-stress only adds to the stresses (linear "
              "superposition).");
        return t;
      }();
      return table;
    }
  } // namespace



  void
  ThermalParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Thermal");
    thermal_table().declare(prm);
    prm.leave_subsection();
  }



  void
  ThermalParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Thermal");
    thermal_table().parse(prm, *this);
    prm.leave_subsection();
    AssertThrow(field != TemperatureField::uniform ||
                  reference_temperature + temperature_change > 0.,
                ExcMessage("Thermal/Temperature change = " +
                           prm_string(temperature_change) +
                           " K takes the plate below 0 K (Reference "
                           "temperature = " +
                           prm_string(reference_temperature) + " K)."));
  }



  namespace
  {
    /// The interval ends of R(z)'s quadrature on [0, h]: Chebyshev points
    /// (clustered at both faces, where a power law or a sigmoid with an
    /// index below 1 has an unbounded slope), the end intervals split
    /// geometrically (ratio 10, 14 times), so that Gauss' rule never spans
    /// the singular point's neighbourhood (n = 0.5: 1e-13 K).
    std::vector<double>
    conduction_nodes(const double h)
    {
      const unsigned int  n_intervals = 400;
      std::vector<double> cos_nodes(n_intervals + 1);
      for (unsigned int i = 0; i <= n_intervals; ++i)
        cos_nodes[i] =
          0.5 * h *
          (1. - std::cos(M_PI * static_cast<double>(i) / n_intervals));
      cos_nodes.front()         = 0.;
      cos_nodes.back()          = h;
      const double        first = cos_nodes[1];
      std::vector<double> nodes{0.};
      for (int k = 14; k >= 1; --k)
        nodes.push_back(first * std::pow(10., -k));
      nodes.insert(nodes.end(), cos_nodes.begin() + 1, cos_nodes.end() - 1);
      for (int k = 1; k <= 14; ++k)
        nodes.push_back(h - first * std::pow(10., -k));
      nodes.push_back(h);
      return nodes;
    }
  } // namespace



  TemperatureProfile::TemperatureProfile(
    const ThermalParameters          &parameters,
    const FunctionallyGradedMaterial &material)
    : parameters(parameters)
    , material(material)
    , h(material.thickness())
  {
    if (parameters.field != TemperatureField::conduction)
      return;
    nodes = conduction_nodes(h);
    solve_conduction();
  }



  void
  TemperatureProfile::solve_conduction()
  {
    // k(T): Picard iterations from the linear profile, T of each one from
    // R of the one before (for a constant k the first is exact).
    const double T_b = parameters.bottom_temperature,
                 T_t = parameters.top_temperature;
    for (const double z : nodes)
      {
        node_temperatures.push_back(T_b + (T_t - T_b) * z / h);
        node_slopes.push_back((T_t - T_b) / h);
      }
    const bool varies = material.get_parameters().temperature_dependent();
    for (iterations = 1; iterations <= 200; ++iterations)
      {
        integrate_resistances();
        double change = 0;
        for (unsigned int i = 0; i < nodes.size(); ++i)
          {
            const double T =
              T_b + (T_t - T_b) * resistances[i] / resistances.back();
            change = std::max(change, std::abs(T - node_temperatures[i]));
            node_temperatures[i] = T;
          }
        for (unsigned int i = 0; i < nodes.size(); ++i)
          node_slopes[i] =
            (T_t - T_b) /
            (resistances.back() *
             material.conductivity(nodes[i], node_temperatures[i]));
        if (!varies)
          return;
        if (change <= 1e-10 * std::max(std::abs(T_b), std::abs(T_t)))
          {
            integrate_resistances();
            return;
          }
      }
    AssertThrow(false,
                ExcMessage("Thermal/Temperature field = conduction: the "
                           "temperature-dependent conductivity's fixed-point "
                           "iteration did not converge in 200 iterations; "
                           "check Material/Metal material and Ceramic "
                           "material and the face temperatures."));
  }



  void
  TemperatureProfile::integrate_resistances()
  {
    resistances.assign(nodes.size(), 0.);
    for (unsigned int i = 1; i < nodes.size(); ++i)
      resistances[i] =
        resistances[i - 1] + gauss_resistance(nodes[i - 1], nodes[i]);
  }



  double
  TemperatureProfile::iterate_temperature(const double z) const
  {
    const auto upper = std::upper_bound(nodes.begin(), nodes.end(), z);
    if (upper == nodes.begin())
      return node_temperatures.front();
    if (upper == nodes.end())
      return node_temperatures.back();
    const std::size_t i  = (upper - nodes.begin()) - 1;
    const double      dz = nodes[i + 1] - nodes[i];
    const double      s  = (z - nodes[i]) / dz;
    // Hermite basis on [0, 1].
    const double h00 = (1. + 2. * s) * (1. - s) * (1. - s),
                 h10 = s * (1. - s) * (1. - s), h01 = s * s * (3. - 2. * s),
                 h11 = s * s * (s - 1.);
    return h00 * node_temperatures[i] + h10 * dz * node_slopes[i] +
           h01 * node_temperatures[i + 1] + h11 * dz * node_slopes[i + 1];
  }



  double
  TemperatureProfile::gauss_resistance(const double z0, const double z1) const
  {
    static const QGauss<1> rule(8);
    double                 sum = 0.;
    for (unsigned int q = 0; q < rule.size(); ++q)
      {
        const double z = z0 + (z1 - z0) * rule.point(q)[0];
        sum +=
          rule.weight(q) / material.conductivity(z, iterate_temperature(z));
      }
    return sum * (z1 - z0);
  }



  double
  TemperatureProfile::resistance(const double z) const
  {
    const double zc = std::clamp(z, 0., h);
    const auto   upper =
      std::upper_bound(nodes.begin(), nodes.end(), zc) - nodes.begin();
    const std::size_t i =
      std::min<std::size_t>(std::max<long>(upper - 1, 0), nodes.size() - 1);
    return resistances[i] +
           (zc > nodes[i] ? gauss_resistance(nodes[i], zc) : 0.);
  }



  double
  TemperatureProfile::temperature(const double z) const
  {
    const ThermalParameters &p = parameters;
    switch (p.field)
      {
        case TemperatureField::none:
          return p.reference_temperature;
        case TemperatureField::uniform:
          return p.reference_temperature + p.temperature_change;
        case TemperatureField::linear:
          return p.bottom_temperature +
                 (p.top_temperature - p.bottom_temperature) *
                   std::clamp(z / h, 0., 1.);
        case TemperatureField::conduction:
          return p.bottom_temperature +
                 (p.top_temperature - p.bottom_temperature) * resistance(z) /
                   resistances.back();
      }
    return p.reference_temperature;
  }
} // namespace fgimpact
