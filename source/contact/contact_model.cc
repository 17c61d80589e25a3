#include <deal.II/base/exceptions.h>

#include <fgimpact/base/parameter_table.h>
#include <fgimpact/base/selection.h>
#include <fgimpact/contact/contact_model.h>
#include <fgimpact/contact/resolved_contact.h>

#include <cmath>
#include <sstream>

namespace fgimpact
{
  namespace
  {
    /// The names of Contact/Gap shape: whether the gap is the paraboloid's.
    const SelectionTable<bool> &
    gap_shape_names()
    {
      static const SelectionTable<bool> names = {{"sphere", false},
                                                 {"paraboloid", true}};
      return names;
    }

    /// The names of Contact/Stabilization: whether the mass is modified.
    const SelectionTable<bool> &
    stabilization_names()
    {
      static const SelectionTable<bool> names = {{"modified mass", true},
                                                 {"none", false}};
      return names;
    }
  } // namespace


  namespace
  {
    /**
     * Solve alpha + s F(alpha) = alpha_tilde by Newton's method.
     * R(alpha) = alpha + s F(alpha) - alpha_tilde is increasing and convex
     * for alpha > 0 and R(alpha_tilde) >= 0, so Newton started at
     * alpha_tilde decreases monotonically to the root.  Returns the number
     * of iterations, or invalid_unsigned_int on failure.
     */
    unsigned int
    solve_contact_newton(const HertzContactLaw &law,
                         const double           s,
                         const double           alpha_tilde,
                         const NewtonControl   &newton,
                         double                &alpha)
    {
      alpha = alpha_tilde;
      if (alpha_tilde <= 0.)
        return 0; // no contact: F = 0 satisfies the equation exactly
      for (unsigned int it = 1; it <= newton.max_iterations; ++it)
        {
          const double R     = alpha + s * law.force(alpha) - alpha_tilde;
          const double dR    = 1. + s * law.force_derivative(alpha);
          const double delta = -R / dR;
          alpha += delta;
          if (!std::isfinite(alpha))
            break;
          if (std::abs(delta) <= newton.tolerance * std::abs(alpha))
            return it;
        }
      return numbers::invalid_unsigned_int;
    }
  } // namespace



  HertzNodeContact::HertzNodeContact(const HertzContactLaw &law,
                                     const PlateModel      &plate,
                                     const Point<2>        &impact_point)
    : law(law)
  {
    const auto [dof, vertex] = plate.nearest_top_vertex_dof(impact_point, 2);
    dofs                     = {dof};
    node                     = vertex;
    // Only the owner knows for sure whether the DoF is constrained.
    const bool constrained =
      Utilities::MPI::max((plate.locally_owned_dofs().is_element(dof) &&
                           plate.get_constraints().is_constrained(dof)) ?
                            1u :
                            0u,
                          plate.get_mpi_communicator()) == 1u;
    AssertThrow(!constrained,
                ExcMessage("Impactor/Impact point: the nearest top-surface "
                           "node lies on a supported face; move the impact "
                           "point inside the plate."));
    node_owner  = plate.dof_owner(dof);
    node_offset = Point<2>(node[0], node[1]).distance(impact_point);
    share       = plate.get_geometry().share();
    if (node_offset <= 1e-9 * plate.get_geometry().length())
      node_offset_note_needed = false;
  }



  void
  HertzNodeContact::solve_implicit(const Vector<double>     &u_free,
                                   const FullMatrix<double> &C,
                                   const ColumnRequest &,
                                   const double         w_free,
                                   const double         c_b,
                                   const NewtonControl &newton,
                                   ContactState        &state) const
  {
    const double W_star     = -u_free[0];
    const double chi        = C(0, 0);
    const double s          = c_b + chi;
    state.newton_iterations = solve_contact_newton(
      law, share * s, w_free - W_star, newton, state.alpha);
    state.force             = share * law.force(state.alpha);
    state.forces            = {state.force};
    state.node_displacement = -W_star - state.force * chi;
  }



  void
  HertzNodeContact::evaluate_explicit(const Vector<double> &u_c,
                                      const double          w,
                                      ContactState         &state) const
  {
    state.node_displacement = u_c[0];
    state.alpha             = w + state.node_displacement;
    state.force             = share * law.force(state.alpha);
    state.forces            = {state.force};
    state.newton_iterations = 0;
  }



  double
  HertzNodeContact::potential(const ContactState &state) const
  {
    return share * law.potential(state.alpha);
  }



  double
  HertzNodeContact::stiffness_bound(const double mass, const double V0) const
  {
    // dF/dalpha at the half-space maximum indentation (closed form): the
    // plate only lowers the indentation.
    // mass is the part's share of the ball's (the stepper's).
    const double K_hertz = law.force(1.);
    const double alpha_max =
      std::pow(1.25 * (mass / share) * V0 * V0 / K_hertz, 0.4);
    return share * law.force_derivative(alpha_max);
  }



  std::string
  HertzNodeContact::description() const
  {
    std::ostringstream s;
    s << "Q_alpha = " << law.contact_modulus() / 1e9
      << " GPa, beta K_h = " << law.force(1.) << " N/m^1.5\n"
      << "  contact node (" << node[0] << ", " << node[1] << ", " << node[2]
      << ") m, owned by MPI rank " << node_owner;
    return s.str();
  }



  std::string
  HertzNodeContact::warning() const
  {
    if (!node_offset_note_needed)
      return "";
    std::ostringstream s;
    s << "note: no node lies at the impact point; the contact force acts at "
         "the nearest top node, "
      << node_offset * 1e3
      << " mm away (choose Subdivisions so that a node lies under the impact "
         "point)";
    return s.str();
  }



  ContactConstants
  HertzNodeContact::constants() const
  {
    ContactConstants c;
    c.contact_modulus     = law.contact_modulus();
    c.contact_stiffness   = law.force(1.); // beta K_h
    c.contact_node_offset = node_offset;
    c.contact_node_owner  = node_owner;
    return c;
  }



  HertzMidplaneContact::HertzMidplaneContact(const HertzContactLaw &law,
                                             const PlateModel      &plate,
                                             const Point<2> &impact_point)
    : law(law)
    , node_contact(law, plate, impact_point)
  {
    const double h           = plate.get_geometry().thickness();
    const auto [dof, vertex] = plate.nearest_vertex_dof(
      Point<3>(impact_point[0], impact_point[1], 0.5 * h), 2);
    AssertThrow(std::abs(vertex[2] - 0.5 * h) <= 1e-9 * h,
                ExcMessage("Contact/Model = hertz midplane needs a vertex on "
                           "the mid-plane: make Geometry/Subdivisions z "
                           "even."));
    mid_node = vertex;
    dofs     = {node_contact.contact_dofs()[0], dof};
    share    = plate.get_geometry().share();
  }



  void
  HertzMidplaneContact::solve_implicit(const Vector<double>     &u_free,
                                       const FullMatrix<double> &C,
                                       const ColumnRequest &,
                                       const double         w_free,
                                       const double         c_b,
                                       const NewtonControl &newton,
                                       ContactState        &state) const
  {
    // alpha = w + u_mid = (w_free - c_b F) + (u_free_mid - C_mt F).
    const double s          = c_b + C(1, 0);
    state.newton_iterations = solve_contact_newton(
      law, share * s, w_free + u_free[1], newton, state.alpha);
    state.force             = share * law.force(state.alpha);
    state.forces            = {state.force, 0.};
    state.node_displacement = u_free[0] - C(0, 0) * state.force;
  }



  void
  HertzMidplaneContact::evaluate_explicit(const Vector<double> &u_c,
                                          const double          w,
                                          ContactState         &state) const
  {
    state.node_displacement = u_c[0];
    state.alpha             = w + u_c[1];
    state.force             = share * law.force(state.alpha);
    state.forces            = {state.force, 0.};
    state.newton_iterations = 0;
  }



  double
  HertzMidplaneContact::potential(const ContactState &state) const
  {
    return share * law.potential(state.alpha);
  }



  double
  HertzMidplaneContact::stiffness_bound(const double mass,
                                        const double V0) const
  {
    return node_contact.stiffness_bound(mass, V0);
  }



  std::string
  HertzMidplaneContact::description() const
  {
    std::ostringstream s;
    s << node_contact.description() << "; indentation from the mid-plane "
      << "node (" << mid_node[0] << ", " << mid_node[1] << ", " << mid_node[2]
      << ") m";
    return s.str();
  }



  std::string
  HertzMidplaneContact::warning() const
  {
    return node_contact.warning();
  }



  ContactConstants
  HertzMidplaneContact::constants() const
  {
    return node_contact.constants();
  }



  namespace
  {
    /// What a contact model's factory may read (create_contact_model()'s
    /// arguments).
    struct ContactModelInputs
    {
      const ContactModelParameters &parameters;
      const HertzContactLaw        &law;
      const PlateModel             &plate;
      double                        sphere_radius;
      Point<2>                      impact_point;
      double                        expected_radius;
      double                        reference_modulus;
      double                        ball_modulus;
    };

    using ContactModelFactory =
      std::unique_ptr<ContactModel> (*)(const ContactModelInputs &);
    using Model = ContactModelParameters::Model;

    /// Every contact model: name, value, help, factory.  A new model is
    /// its class and one row here (and its enum value).
    const Registry<Model, ContactModelFactory> &
    contact_model_registry()
    {
      static const Registry<Model, ContactModelFactory> registry = {
        {"hertz node",
         Model::hertz_node,
         "the paper's Eq. 3.14, the modified Hertz law as a point force at "
         "the top node nearest to the impact point (its force depends on "
         "the element size there: it does not converge under refinement).",
         [](const ContactModelInputs &in) -> std::unique_ptr<ContactModel> {
           return std::make_unique<HertzNodeContact>(in.law,
                                                     in.plate,
                                                     in.impact_point);
         }},
        {"hertz midplane",
         Model::hertz_midplane,
         "the same law with the indentation measured from the mid-plane "
         "vertex under the impact point (the plate theories' alpha; "
         "converges; needs an even Subdivisions z); the force is still a "
         "point force at the top node.",
         [](const ContactModelInputs &in) -> std::unique_ptr<ContactModel> {
           return std::make_unique<HertzMidplaneContact>(in.law,
                                                         in.plate,
                                                         in.impact_point);
         }},
        {"resolved sphere",
         Model::resolved_sphere,
         "a sphere in frictionless unilateral contact with every top "
         "node near the impact point (no contact law; converges with "
         "Geometry/Contact refinement levels, whose default auto resolves "
         "the contact radius; an elastic Impactor/Material adds the ball's "
         "Boussinesq surface compliance; implicit scheme only).",
         [](const ContactModelInputs &in) -> std::unique_ptr<ContactModel> {
           const ContactModelParameters &p = in.parameters;
           return std::make_unique<ResolvedSphereContact>(
             in.plate,
             in.sphere_radius,
             in.impact_point,
             p.candidate_radius > 0. ?
               p.candidate_radius :
               ResolvedSphereContact::candidate_radius_factor *
                   in.expected_radius +
                 2. * in.plate.smallest_cell_size(),
             create_sphere_profile(in.sphere_radius, p.paraboloid_gap),
             in.reference_modulus,
             p.modified_mass,
             in.ball_modulus);
         }}};
      return registry;
    }
  } // namespace



  const SelectionTable<ContactModelParameters::Model> &
  ContactModelParameters::model_names()
  {
    return contact_model_registry();
  }



  namespace
  {
    /// The entries of ContactModelParameters that set a member as they stand.
    const ParameterTable<ContactModelParameters> &
    contact_model_table()
    {
      using P                              = ContactModelParameters;
      static const ParameterTable<P> table = [] {
        ParameterTable<P> t;
        t.add("Model",
              &P::model,
              ContactModelParameters::model_names(),
              contact_model_registry().help());
        t.add(
          "Gap shape",
          &P::paraboloid_gap,
          gap_shape_names(),
          "resolved sphere: the height of the ball's surface above its lowest "
          "point at distance r, R - sqrt(R^2 - r^2) (sphere) or the Hertz "
          "approximation r^2/(2R) (paraboloid).");
        t.add(
          "Stabilization",
          &P::modified_mass,
          stabilization_names(),
          "resolved sphere: modified mass = the contact candidates' z "
          "degrees of freedom carry no mass (Khenous, Laborde & Renard 2008), "
          "which removes the chatter and the energy error of Newmark with hard "
          "contact (doc/contact.md); the mass removed vanishes with the "
          "element size and is logged. none = the consistent mass.");
        t.add(
          "Candidate radius",
          &P::candidate_radius,
          Patterns::Double(0., 10.),
          "resolved sphere: top nodes within this distance of the impact "
          "point are contact candidates (one solve each at set-up); 0 = "
          "automatic, 1.5 times the largest contact radius of the ball on a "
          "half-space of the top face's modulus plus two of the smallest "
          "elements. Unit: m.");
        return t;
      }();
      return table;
    }
  } // namespace



  void
  ContactModelParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact");
    {
      contact_model_table().declare(prm);
    }
    prm.leave_subsection();
  }



  void
  ContactModelParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact");
    contact_model_table().parse(prm, *this);
    prm.leave_subsection();
  }



  std::unique_ptr<ContactModel>
  create_contact_model(const ContactModelParameters &parameters,
                       const HertzContactLaw        &law,
                       const PlateModel             &plate,
                       const double                  sphere_radius,
                       const Point<2>               &impact_point,
                       const double                  expected_radius,
                       const double                  reference_modulus,
                       const double                  ball_modulus)
  {
    return contact_model_registry().factory(parameters.model)(
      {parameters,
       law,
       plate,
       sphere_radius,
       impact_point,
       expected_radius,
       reference_modulus,
       ball_modulus});
  }
} // namespace fgimpact
