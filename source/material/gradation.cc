#include <deal.II/base/exceptions.h>

#include <fgimpact/base/files.h>
#include <fgimpact/material/gradation.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

namespace fgimpact
{
  using dealii::ExcMessage;

  const SelectionTable<Homogenization> &
  homogenization_names()
  {
    static const SelectionTable<Homogenization> names = {
      {"rule of mixtures", Homogenization::rule_of_mixtures},
      {"Mori-Tanaka", Homogenization::mori_tanaka}};
    return names;
  }


  IsotropicProperties
  homogenize(const Constituents  &constituents,
             const double         metal_fraction,
             const Homogenization homogenization)
  {
    const IsotropicProperties &m = constituents.metal,
                              &c = constituents.ceramic;
    const double Vm              = metal_fraction;
    // The rule of mixtures on E and rho is Eq. 2.1's P_c + (P_m - P_c) V_m,
    // written exactly as before the gradations were added (same rounding).
    const double rho = c.rho + (m.rho - c.rho) * Vm;
    if (homogenization == Homogenization::rule_of_mixtures)
      return {c.E + (m.E - c.E) * Vm, c.nu + (m.nu - c.nu) * Vm, rho};

    // Mori-Tanaka (Benveniste's form, metal matrix m, ceramic inclusions of
    // volume fraction V_c = 1 - V_m):
    //   K = K_m + V_c (K_c - K_m) / (1 + V_m (K_c - K_m) / (K_m + 4/3 G_m)),
    //   G = G_m + V_c (G_c - G_m) / (1 + V_m (G_c - G_m) / (G_m + f_m)),
    //   f_m = G_m (9 K_m + 8 G_m) / (6 (K_m + 2 G_m)),
    // then E = 9 K G / (3 K + G), nu = (3 K - 2 G) / (2 (3 K + G)).
    const auto bulk = [](const IsotropicProperties &p) {
      return p.E / (3. * (1. - 2. * p.nu));
    };
    const auto shear = [](const IsotropicProperties &p) {
      return p.E / (2. * (1. + p.nu));
    };
    const double Km = bulk(m), Gm = shear(m), Kc = bulk(c), Gc = shear(c);
    const double Vc = 1. - Vm;
    const double fm = Gm * (9. * Km + 8. * Gm) / (6. * (Km + 2. * Gm));
    const double K =
      Km + Vc * (Kc - Km) / (1. + Vm * (Kc - Km) / (Km + 4. / 3. * Gm));
    const double G = Gm + Vc * (Gc - Gm) / (1. + Vm * (Gc - Gm) / (Gm + fm));
    return {9. * K * G / (3. * K + G),
            (3. * K - 2. * G) / (2. * (3. * K + G)),
            rho};
  }



  namespace
  {
    /// Power law (Eq. 2.1) and sigmoid: a metal volume fraction, then the
    /// homogenization.
    class VolumeFractionLaw : public GradationLaw
    {
    public:
      VolumeFractionLaw(const Constituents  &constituents,
                        const Homogenization homogenization,
                        const double         index,
                        const bool           sigmoid)
        : constituents(constituents)
        , homogenization(homogenization)
        , index(index)
        , sigmoid(sigmoid)
      {}

      IsotropicProperties
      properties(const double zeta) const override
      {
        return homogenize(constituents, metal_fraction(zeta), homogenization);
      }

      double
      metal_fraction(const double zeta) const override
      {
        // pow(0, 0) = 1 in C++: n = 0 is pure metal, as Eq. 2.1 requires
        // (for the sigmoid law, a uniform 50/50 mixture).
        if (!sigmoid)
          return std::pow(zeta, index);
        if (zeta <= 0.5)
          return 0.5 * std::pow(2. * zeta, index);
        return 1. - 0.5 * std::pow(2. * (1. - zeta), index);
      }

      bool
      constant_poissons_ratio() const override
      {
        return homogenization == Homogenization::rule_of_mixtures &&
               constituents.metal.nu == constituents.ceramic.nu;
      }

      double
      total_metal_volume_fraction() const override
      {
        // The sigmoid law is antisymmetric about the mid-plane: half metal.
        return sigmoid ? 0.5 : 1. / (1. + index);
      }

    private:
      const Constituents   constituents;
      const Homogenization homogenization;
      const double         index;
      const bool           sigmoid;
    };



    /// P(zeta) = P_c exp(ln(P_m / P_c) zeta) for E and rho; nu (which may
    /// be zero or negative) linear, nu_c + (nu_m - nu_c) zeta.
    class ExponentialLaw : public GradationLaw
    {
    public:
      explicit ExponentialLaw(const Constituents &constituents)
        : c(constituents.ceramic)
        , m(constituents.metal)
      {}

      IsotropicProperties
      properties(const double zeta) const override
      {
        return {c.E * std::exp(std::log(m.E / c.E) * zeta),
                c.nu + (m.nu - c.nu) * zeta,
                c.rho * std::exp(std::log(m.rho / c.rho) * zeta)};
      }

      bool
      constant_poissons_ratio() const override
      {
        return m.nu == c.nu;
      }

    private:
      const IsotropicProperties c, m;
    };



    class TabulatedLaw : public GradationLaw
    {
    public:
      explicit TabulatedLaw(const std::string &filename)
        : table(filename)
      {}

      IsotropicProperties
      properties(const double zeta) const override
      {
        return table(zeta);
      }

      bool
      constant_poissons_ratio() const override
      {
        return table.constant_poissons_ratio();
      }

    private:
      const TabulatedProfile table;
    };
  } // namespace



  namespace
  {
    /// What a gradation law's factory may read.
    struct GradationInputs
    {
      Homogenization     homogenization;
      const Constituents constituents;
      double             index;
      std::string        profile_file;
    };

    using GradationFactory =
      std::unique_ptr<GradationLaw> (*)(const GradationInputs &);

    /// Every gradation law: name, value, help, factory.  A new law is its
    /// class above and one row here (and its enum value).
    const Registry<Gradation, GradationFactory> &
    gradation_registry()
    {
      static const Registry<Gradation, GradationFactory> registry = {
        {"power law",
         Gradation::power_law,
         "metal volume fraction V_m = zeta^n (Eq. 2.1).",
         [](const GradationInputs &in) -> std::unique_ptr<GradationLaw> {
           return std::make_unique<VolumeFractionLaw>(in.constituents,
                                                      in.homogenization,
                                                      in.index,
                                                      false);
         }},
        {"exponential",
         Gradation::exponential,
         "P = P_c exp(ln(P_m/P_c) zeta) for E and rho, nu = nu_c + (nu_m - "
         "nu_c) zeta (Power-law index unused).",
         [](const GradationInputs &in) -> std::unique_ptr<GradationLaw> {
           return std::make_unique<ExponentialLaw>(in.constituents);
         }},
        {"sigmoid",
         Gradation::sigmoid,
         "Chung & Chi's two power laws, V_m = (2 zeta)^n / 2 for zeta <= "
         "1/2, 1 - (2 - 2 zeta)^n / 2 above (n = Power-law index).",
         [](const GradationInputs &in) -> std::unique_ptr<GradationLaw> {
           return std::make_unique<VolumeFractionLaw>(in.constituents,
                                                      in.homogenization,
                                                      in.index,
                                                      true);
         }},
        {"tabulated",
         Gradation::tabulated,
         "E, nu, rho interpolated linearly in Profile file.",
         [](const GradationInputs &in) -> std::unique_ptr<GradationLaw> {
           return std::make_unique<TabulatedLaw>(in.profile_file);
         }}};
      return registry;
    }
  } // namespace



  const SelectionTable<Gradation> &
  gradation_names()
  {
    return gradation_registry();
  }



  std::string
  gradation_help()
  {
    return gradation_registry().help();
  }



  std::unique_ptr<GradationLaw>
  create_gradation_law(const Gradation      gradation,
                       const Homogenization homogenization,
                       const Constituents  &constituents,
                       const double         index,
                       const std::string   &profile_file)
  {
    auto law = gradation_registry().factory(gradation)(
      {homogenization, constituents, index, profile_file});
    AssertThrow(std::isfinite(law->total_metal_volume_fraction()) ||
                  homogenization == Homogenization::rule_of_mixtures,
                ExcMessage("Material/Homogenization = Mori-Tanaka needs a "
                           "volume fraction: Material/Gradation = power law "
                           "or sigmoid (exponential and tabulated give the "
                           "properties themselves)."));
    return law;
  }



  TabulatedProfile::TabulatedProfile(const std::string &filename)
  {
    const std::string where = "Material/Profile file '" + filename + "'";
    // A regular file of a sensible size, as the .prm (a FIFO or device
    // would block or never end).
    std::istringstream in(read_named_file(filename, where, "a CSV profile"));
    std::vector<unsigned int> line_numbers;
    std::string               line;
    bool                      header_allowed = true;
    for (unsigned int number = 1; std::getline(in, line); ++number)
      {
        line = line.substr(0, line.find('#'));
        std::replace(line.begin(), line.end(), ',', ' ');
        std::replace(line.begin(), line.end(), '\r', ' ');
        std::istringstream  fields(line);
        std::vector<double> row;
        std::string         field;
        bool                numeric = true;
        while (fields >> field)
          {
            std::size_t end = 0;
            try
              {
                row.push_back(std::stod(field, &end));
              }
            catch (...)
              {
                end = 0;
              }
            numeric = numeric && end == field.size() && end > 0;
          }
        if (row.empty() && numeric) // blank or comment line
          continue;
        if (!numeric && row.empty() && header_allowed) // z/h, E, nu, rho
          {
            header_allowed = false;
            continue;
          }
        header_allowed = false;
        AssertThrow(numeric && row.size() == 4,
                    ExcMessage(where + ", line " + std::to_string(number) +
                               ": expected 4 numbers (z/h, E in Pa, nu, rho "
                               "in kg/m^3)."));
        zeta.push_back(row[0]);
        values.push_back({row[1], row[2], row[3]});
        line_numbers.push_back(number);
      }
    check(line_numbers, where);
  }



  TabulatedProfile::TabulatedProfile(
    const std::vector<std::vector<double>> &rows,
    const std::string                      &name)
  {
    std::vector<unsigned int> line_numbers;
    for (const auto &row : rows)
      {
        AssertThrow(row.size() == 4,
                    ExcMessage(name + ", line " +
                               std::to_string(line_numbers.size() + 1) +
                               ": expected 4 numbers."));
        zeta.push_back(row[0]);
        values.push_back({row[1], row[2], row[3]});
        line_numbers.push_back(line_numbers.size() + 1);
      }
    check(line_numbers, name);
  }



  void
  TabulatedProfile::check(const std::vector<unsigned int> &line_numbers,
                          const std::string               &name) const
  {
    AssertThrow(zeta.size() >= 2, ExcMessage(name + ": fewer than 2 rows."));
    for (unsigned int i = 0; i < zeta.size(); ++i)
      {
        const std::string at =
          name + ", line " + std::to_string(line_numbers[i]) + ": ";
        const IsotropicProperties &v = values[i];
        AssertThrow(std::isfinite(zeta[i]) && zeta[i] >= 0. && zeta[i] <= 1.,
                    ExcMessage(at + "z/h outside [0, 1]."));
        AssertThrow(i == 0 || zeta[i] > zeta[i - 1],
                    ExcMessage(at + "z/h not strictly increasing."));
        AssertThrow(std::isfinite(v.E) && v.E > 0.,
                    ExcMessage(at + "E must be positive (Pa)."));
        AssertThrow(std::isfinite(v.nu) && v.nu > -1. && v.nu < 0.5,
                    ExcMessage(at + "nu must lie in (-1, 0.5)."));
        AssertThrow(std::isfinite(v.rho) && v.rho > 0.,
                    ExcMessage(at + "rho must be positive (kg/m^3)."));
      }
    AssertThrow(zeta.front() == 0.,
                ExcMessage(name + ", line " +
                           std::to_string(line_numbers.front()) +
                           ": the first row must be at z/h = 0."));
    AssertThrow(zeta.back() == 1.,
                ExcMessage(name + ", line " +
                           std::to_string(line_numbers.back()) +
                           ": the last row must be at z/h = 1."));
  }



  IsotropicProperties
  TabulatedProfile::operator()(const double z) const
  {
    const double x = std::clamp(z, 0., 1.);
    // The row interval [zeta_i, zeta_{i+1}] that holds x.
    const std::size_t i =
      std::min<std::size_t>(std::upper_bound(zeta.begin(), zeta.end(), x) -
                              zeta.begin(),
                            zeta.size() - 1) -
      1;
    const double               t = (x - zeta[i]) / (zeta[i + 1] - zeta[i]);
    const IsotropicProperties &a = values[i], &b = values[i + 1];
    return {a.E + t * (b.E - a.E),
            a.nu + t * (b.nu - a.nu),
            a.rho + t * (b.rho - a.rho)};
  }



  bool
  TabulatedProfile::constant_poissons_ratio() const
  {
    for (const auto &v : values)
      if (v.nu != values.front().nu)
        return false;
    return true;
  }
} // namespace fgimpact
