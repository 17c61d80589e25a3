#include <fgimpact/base/parameter_table.h>
#include <fgimpact/base/selection.h>
#include <fgimpact/contact/impactor.h>

#include <cmath>
#include <cstdio>
#include <limits>

namespace fgimpact
{
  namespace
  {
    /// The names of Impactor/Material: whether the ball is elastic.
    const SelectionTable<bool> &
    ball_material_names()
    {
      static const SelectionTable<bool> names = {{"rigid", false},
                                                 {"elastic", true}};
      return names;
    }
  } // namespace


  namespace
  {
    /// The entries of Impactor::Parameters that set a member as they stand.
    const ParameterTable<Impactor::Parameters> &
    impactor_table()
    {
      using P                              = Impactor::Parameters;
      static const ParameterTable<P> table = [] {
        ParameterTable<P> t;
        t.add("Radius",
              &P::radius,
              Patterns::Double(1e-6, 10.),
              "Radius R of the spherical impactor. Unit: m.");
        t.add("Density",
              &P::density,
              Patterns::Double(1e-3, 1e6),
              "Mass density rho_i of the impactor; its mass is "
              "4/3 pi R^3 rho_i unless 'Mass' is set. "
              "Unit: kg/m^3.");
        t.add("Mass",
              &P::given_mass,
              Patterns::Double(0., 1e6),
              "Impactor mass given directly, overriding the one "
              "computed from radius and density; 0 = compute it. "
              "Unit: kg.");
        t.add("Initial velocity",
              &P::initial_velocity,
              Patterns::Double(1e-9, 1e3),
              "Impact velocity V0 towards the plate (along -z), "
              "Eq. 2.16. Unit: m/s.");
        t.add("Impact point x",
              &P::impact_x,
              Patterns::Double(-1., 1e3),
              "x coordinate of the impact point on the top face; a "
              "negative value means the centre a/2. The contact "
              "force acts at the top-surface node nearest to it. "
              "Unit: m.");
        t.add("Impact point y",
              &P::impact_y,
              Patterns::Double(-1., 1e3),
              "y coordinate of the impact point; negative means "
              "b/2. Unit: m.");
        t.add("Material",
              &P::elastic,
              ball_material_names(),
              "rigid: Q_alpha = Q_zp (Eq. 2.7). elastic: "
              "1/Q_alpha = 1/Q_zi + 1/Q_zp (Eq. 2.6) with the "
              "impactor's Young's modulus and Poisson's ratio.");
        t.add("Young's modulus",
              &P::youngs_modulus,
              Patterns::Double(1e3, 1e15),
              "Young's modulus E_i of an elastic impactor. Unit: "
              "Pa.");
        t.add("Poisson's ratio",
              &P::poissons_ratio,
              Patterns::Double(-0.99, 0.49),
              "Poisson's ratio nu_i of an elastic impactor. "
              "Dimensionless.");
        return t;
      }();
      return table;
    }
  } // namespace



  void
  Impactor::Parameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Impactor");
    {
      impactor_table().declare(prm);
    }
    prm.leave_subsection();
  }



  void
  Impactor::Parameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Impactor");
    {
      impactor_table().parse(prm, *this);
    }
    prm.leave_subsection();
  }



  Impactor::Impactor(const Parameters &parameters)
    : parameters(parameters)
  {}



  double
  Impactor::mass() const
  {
    if (parameters.given_mass > 0.)
      return parameters.given_mass;
    return 4. / 3. * M_PI * std::pow(parameters.radius, 3) * parameters.density;
  }



  double
  Impactor::indentation_modulus() const
  {
    if (!parameters.elastic)
      return std::numeric_limits<double>::infinity();
    return elastic_indentation_modulus();
  }



  double
  Impactor::elastic_indentation_modulus() const
  {
    return parameters.youngs_modulus /
           (1. - parameters.poissons_ratio * parameters.poissons_ratio);
  }



  double
  Impactor::lowest_vibration_period() const
  {
    if (!parameters.elastic)
      return 0.;
    const double R   = parameters.radius;
    const double rho = mass() / (4. / 3. * M_PI * R * R * R);
    const double c_s = std::sqrt(parameters.youngs_modulus /
                                 (2. * (1. + parameters.poissons_ratio) * rho));
    return 2. * M_PI * R / (2.64 * c_s);
  }



  std::string
  Impactor::vibration_report(const double T_contact) const
  {
    // Hertz's elastic ball is quasi-static: its own vibration must be much
    // faster than the contact (Johnson, Contact Mechanics, section 11.4).
    const double T_ball = lowest_vibration_period();
    if (T_ball == 0.)
      return "";
    const bool slow = T_ball > 0.2 * T_contact;
    char       text[400];
    std::snprintf(text,
                  sizeof(text),
                  "%selastic ball: lowest vibration period %.3g us, %.1f %% "
                  "of Hertz's contact duration %.4g us%s",
                  slow ? "WARNING: " : "",
                  T_ball * 1e6,
                  100. * T_ball / T_contact,
                  T_contact * 1e6,
                  slow ? " (above 20 %: the ball's waves matter; Impactor/"
                         "Radius or the impact is too short for Hertz's "
                         "quasi-static ball)" :
                         "");
    return text;
  }



  Point<2>
  Impactor::impact_point(const double a, const double b) const
  {
    return Point<2>(parameters.impact_x < 0 ? a / 2 : parameters.impact_x,
                    parameters.impact_y < 0 ? b / 2 : parameters.impact_y);
  }
} // namespace fgimpact
