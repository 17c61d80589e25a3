#include <deal.II/base/exceptions.h>

#include <fgimpact/base/parameter_table.h>
#include <fgimpact/base/selection.h>
#include <fgimpact/contact/contact_law.h>

#include <cmath>

namespace fgimpact
{
  namespace
  {
    /// The names of Contact/Plate modulus.
    const SelectionTable<HertzContactLaw::PlateModulus> &
    plate_modulus_names()
    {
      using M                              = HertzContactLaw::PlateModulus;
      static const SelectionTable<M> names = {
        {"turner graded", M::turner_graded},
        {"isotropic top", M::isotropic_top}};
      return names;
    }
  } // namespace


  double
  turner_apparent_modulus(const TransverselyIsotropicConstants &c)
  {
    const double one_m_nu2 = 1. - c.nu_xy * c.nu_xy;
    const double alpha_1 =
      std::sqrt((c.E_x / c.E_z - c.nu_xz * c.nu_xz) / one_m_nu2);
    const double alpha_2 =
      (c.E_x / (2. * c.G_xz) - c.nu_xz * (1. + c.nu_xy)) / one_m_nu2;
    // Unit: 1/Pa.  The paper's Eq. 2.10 puts the square root over the whole
    // product, which is dimensionally inconsistent.
    const double alpha_3 =
      std::sqrt((alpha_1 + alpha_2) / 2.) * (1. - c.nu_xy) / c.G_xy;
    return 2. / (alpha_1 * alpha_3);
  }



  double
  delafargue_ulm_indentation_modulus(const TransverselyIsotropicConstants &c)
  {
    // Stiffness constants from the compliances: with x, y the plane of
    // isotropy, the normal block of the compliance matrix is
    //   [ 1/Ex, -nxy/Ex, -nxz/Ex; -nxy/Ex, 1/Ex, -nxz/Ex; -nxz/Ex, -nxz/Ex,
    //   1/Ez ].
    const double s11 = 1. / c.E_x, s12 = -c.nu_xy / c.E_x,
                 s13 = -c.nu_xz / c.E_x, s33 = 1. / c.E_z;
    // Inverse of the symmetric 3x3 block restricted to the xy-symmetric
    // deformations (closed form).
    const double det = (s11 - s12) * ((s11 + s12) * s33 - 2. * s13 * s13);
    const double C11 = (s11 * s33 - s13 * s13) / det;
    const double C13 = (-s13 * (s11 - s12)) / det;
    const double C33 = (s11 * s11 - s12 * s12) / det;
    const double C44 = c.G_xz;
    return 2. * std::sqrt((C11 * C33 - C13 * C13) / C11 /
                          (1. / C44 + 2. / (std::sqrt(C11 * C33) + C13)));
  }



  namespace
  {
    /// The entries of HertzContactLaw::Parameters that set a member as they
    /// stand.
    const ParameterTable<HertzContactLaw::Parameters> &
    contact_law_table()
    {
      using P                              = HertzContactLaw::Parameters;
      static const ParameterTable<P> table = [] {
        ParameterTable<P> t;
        t.add(
          "Plate modulus",
          &P::plate_modulus,
          plate_modulus_names(),
          "turner graded: the paper's modified Hertz law, Turner's apparent "
          "modulus (Eq. 2.9, consistent form) of the contact region whose "
          "Voigt/Reuss properties follow from V_m = 1/(1+n) (Eqs. 2.2-2.3). "
          "isotropic top: the plain Hertz law with the top face's "
          "Q = E_m/(1 - nu^2).");
        t.add("Swanson beta",
              &P::swanson_beta,
              Patterns::Double(1e-6, 1e6),
              "Swanson's empirical finite-thickness factor beta of "
              "Eq. 2.8, F = beta K_h alpha^{3/2}. Dimensionless.");
        t.add("Contact stiffness",
              &P::given_stiffness,
              Patterns::Double(0., 1e20),
              "K_h given directly (e.g. measured), overriding the "
              "law above (Swanson beta still multiplies it); 0 = "
              "compute it from the law. Unit: N/m^1.5.");
        return t;
      }();
      return table;
    }
  } // namespace



  void
  HertzContactLaw::Parameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact");
    {
      contact_law_table().declare(prm);
    }
    prm.leave_subsection();
  }



  void
  HertzContactLaw::Parameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact");
    {
      contact_law_table().parse(prm, *this);
    }
    prm.leave_subsection();
  }



  TransverselyIsotropicConstants
  HertzContactLaw::contact_region_constants(
    const FunctionallyGradedMaterial &material)
  {
    const auto        &p      = material.get_parameters();
    const Constituents phases = p.constituents();
    double             E_reuss, G_reuss, E_voigt, nu;
    if (material.grades_volume_fraction())
      {
        // Eq. 2.3 on the two phases with their total volume fractions
        // (power law 1/(1+n), sigmoid 1/2): Reuss (series) through the
        // thickness, Voigt (parallel) in plane.
        const double Vm   = material.total_metal_volume_fraction();
        const double Vc   = 1. - Vm;
        const double nu_m = phases.metal.nu, nu_c = phases.ceramic.nu;
        const double Gm = p.metal_youngs_modulus / (2. * (1. + nu_m));
        const double Gc = p.ceramic_youngs_modulus / (2. * (1. + nu_c));
        E_reuss =
          1. / (Vc / p.ceramic_youngs_modulus + Vm / p.metal_youngs_modulus);
        G_reuss = 1. / (Vc / Gc + Vm / Gm);
        E_voigt = p.ceramic_youngs_modulus * Vc + p.metal_youngs_modulus * Vm;
        nu      = (nu_m == nu_c ? nu_m : Vc * nu_c + Vm * nu_m);
      }
    else
      {
        // Exponential and tabulated profiles have no phases: the same
        // averages of the profile itself over the thickness (midpoint rule
        // on 4096 slices, far below the contact law's accuracy).
        const unsigned int n    = 4096;
        const double       h    = material.thickness();
        double             invE = 0, invG = 0, sumE = 0, sumnu = 0;
        for (unsigned int i = 0; i < n; ++i)
          {
            const IsotropicProperties q =
              material.properties((i + 0.5) * h / n);
            invE += 1. / q.E / n;
            invG += 2. * (1. + q.nu) / q.E / n;
            sumE += q.E / n;
            sumnu += q.nu / n;
          }
        E_reuss = 1. / invE;
        G_reuss = 1. / invG;
        E_voigt = sumE;
        nu      = sumnu;
      }

    TransverselyIsotropicConstants c;
    c.E_z  = E_reuss;
    c.G_xz = G_reuss;
    c.E_x  = E_voigt;
    // The paper is silent on the Poisson's ratios of the contact region; with
    // nu constant in both phases we take nu_xy = nu_xz = nu (else its
    // average), and the in-plane shear modulus that transverse isotropy
    // requires.
    c.nu_xy = nu;
    c.nu_xz = nu;
    c.G_xy  = c.E_x / (2. * (1. + nu));
    return c;
  }



  HertzContactLaw::HertzContactLaw(const Parameters                 &parameters,
                                   const FunctionallyGradedMaterial &material,
                                   const Impactor                   &impactor)
    : parameters(parameters)
  {
    const auto &p = material.get_parameters();
    if (parameters.plate_modulus == PlateModulus::turner_graded)
      Q_plate = turner_apparent_modulus(contact_region_constants(material));
    else
      Q_plate =
        p.metal_youngs_modulus / (1. - p.poissons_ratio * p.poissons_ratio);

    // Eq. 2.6; for a rigid impactor 1/Q_zi = 0 and this is Eq. 2.7.
    Q_alpha = 1. / (1. / impactor.indentation_modulus() + 1. / Q_plate);

    K_h = (parameters.given_stiffness > 0. ?
             parameters.given_stiffness :
             4. / 3. * Q_alpha * std::sqrt(impactor.radius()));
  }



  double
  HertzContactLaw::force(const double alpha) const
  {
    return alpha > 0. ?
             parameters.swanson_beta * K_h * alpha * std::sqrt(alpha) :
             0.;
  }



  double
  HertzContactLaw::force_derivative(const double alpha) const
  {
    return alpha > 0. ? 1.5 * parameters.swanson_beta * K_h * std::sqrt(alpha) :
                        0.;
  }



  double
  HertzContactLaw::potential(const double alpha) const
  {
    return alpha > 0. ? 0.4 * parameters.swanson_beta * K_h * alpha * alpha *
                          std::sqrt(alpha) :
                        0.;
  }


  double
  hertz_impact_contact_radius(const double Q,
                              const double R,
                              const double m,
                              const double V0)
  {
    const double K         = 4. / 3. * Q * std::sqrt(R);
    const double alpha_max = std::pow(1.25 * m * V0 * V0 / K, 0.4);
    return std::sqrt(R * alpha_max);
  }


  double
  hertz_impact_duration(const double K, const double m, const double V0)
  {
    const double alpha_max = std::pow(1.25 * m * V0 * V0 / K, 0.4);
    return 2.943 * alpha_max / V0;
  }


  double
  combined_indentation_modulus(const double Q_plate, const double Q_ball)
  {
    return std::isfinite(Q_ball) ? 1. / (1. / Q_plate + 1. / Q_ball) : Q_plate;
  }


  double
  top_face_modulus(const FunctionallyGradedMaterial &material,
                   const double                      thickness)
  {
    const IsotropicProperties top = material.properties(thickness);
    return top.E / (1. - top.nu * top.nu);
  }
} // namespace fgimpact
