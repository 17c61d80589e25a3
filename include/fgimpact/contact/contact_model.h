#ifndef fgimpact_contact_model_h
#define fgimpact_contact_model_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <fgimpact/base/checkpoint.h>
#include <fgimpact/base/selection.h>
#include <fgimpact/contact/complementarity.h>
#include <fgimpact/contact/contact_law.h>
#include <fgimpact/contact/impactor.h>
#include <fgimpact/plate/plate_model.h>

#include <memory>
#include <string>
#include <vector>

namespace fgimpact
{
  using namespace dealii;

  /// A contact model's constants for summary.txt (the whole plate's).
  struct ContactConstants
  {
    double       contact_modulus     = 0; // Pa
    double       contact_stiffness   = 0; // N/m^1.5 (beta K_h)
    double       contact_node_offset = 0; // m, node to impact point
    unsigned int contact_node_owner  = 0; // MPI rank owning its DoF
    /// The whole plate's contact DoFs where the model counts them (0: the
    /// modelled part's candidates stand).
    unsigned int n_contact_candidates = 0;
  };

  /// The contact at the current time, known on every MPI rank.
  struct ContactState
  {
    /// Indentation alpha (m): the largest overlap of ball and plate.
    double alpha = 0;
    /// Total contact force on the ball (N), positive in compression.
    double force = 0;
    /// z displacement of the plate (m, positive up) at the first contact
    /// DoF (the contact node of the Hertz model).
    double node_displacement = 0;
    /// Newton iterations of the last implicit step (0: explicit or no
    /// contact).
    unsigned int newton_iterations = 0;
    /// Force at each contact DoF (N, acting on the plate in -z).
    std::vector<double> forces;
    /// Resolved contact only: nodes with a positive force, the largest
    /// distance of such a node from the impact point (m; the discrete edge
    /// lies before the next node out) and the largest nodal pressure
    /// lambda_j / A_j (Pa).
    unsigned int n_active       = 0;
    double       contact_radius = 0;
    double       max_pressure   = 0;
    /// Resolved contact: a node of the candidate set's outermost ring is
    /// in contact, so the solution may be cut off: grow and repeat.
    bool candidates_exhausted = false;
    /// Resolved contact: the LCP's active-set iteration did not settle and
    /// projected Gauss-Seidel finished the solve; the largest penetration
    /// left (m) either way.
    bool   used_lcp_fallback    = false;
    double residual_penetration = 0;
  };

  /// The stopping rule of a contact model's Newton iteration.
  struct NewtonControl
  {
    double       tolerance      = 1e-3; // relative change of alpha
    unsigned int max_iterations = 50;
  };

  /**
   * The contact between the impactor and the plate's top face, as the
   * ContactCoupler sees it: a set of contact DoFs (z components of top-face
   * nodes, the same global indices on every MPI rank) where non-negative forces
   * lambda_j push the plate down (-z) and the ball up.
   *
   * An implicit step gives the model the contact-free response of plate and
   * ball and the plate's compliance at the contact DoFs,
   *   u_c = u_free - C lambda,  w = w_free - c_b sum_j lambda_j,
   * with C_ij = g_i^T K_eff^{-1} g_j (the Delassus matrix, m/N, constant
   * because K_eff is) and c_b = 1/(m a0) the ball's compliance; the model
   * returns the forces.  An explicit step gives it the positions.  Nothing
   * else of the time loop depends on the model: the coupler grows a
   * resolved contact's candidate set and hands the new contact DoFs (and
   * massless_dofs()) to the plate response.
   */
  class ContactModel
  {
  public:
    virtual ~ContactModel() = default;

    /// The contact DoFs, the same on every rank.
    virtual const std::vector<types::global_dof_index> &
    contact_dofs() const = 0;

    /**
     * Contact forces at t_{n+1} of an implicit step: u_free (m, z
     * displacement at the contact DoFs, positive up), C (m/N), w_free (m,
     * the ball's displacement without contact, positive down), c_b (m/N).
     * A model with compliance_on_demand() asks for C's columns through
     * `columns` (which fills them in C) as the contact reaches them; the
     * others are given C whole (`columns` may be empty).
     * Sets every field of state; newton_iterations is
     * numbers::invalid_unsigned_int if Newton did not converge.
     */
    virtual void
    solve_implicit(const Vector<double>     &u_free,
                   const FullMatrix<double> &C,
                   const ColumnRequest      &columns,
                   const double              w_free,
                   const double              c_b,
                   const NewtonControl      &newton,
                   ContactState             &state) const = 0;

    /// Contact forces of an explicit step at the plate's z displacements
    /// u_c (m) at the contact DoFs and the ball's displacement w (m).
    virtual void
    evaluate_explicit(const Vector<double> &u_c,
                      const double          w,
                      ContactState         &state) const = 0;

    /// Energy stored in the contact (J), 0 for a rigid unilateral contact.
    virtual double
    potential(const ContactState &state) const = 0;

    /// Whether the contact force derives from potential(); if not, the
    /// monitor books the force's work on the approach at the first contact
    /// DoF as the contact energy.
    virtual bool
    has_potential() const
    {
      return true;
    }

    /**
     * An upper bound of the contact's stiffness dF/dalpha (N/m) during an
     * impact of a ball of mass m (kg) at V0 (m/s), for the explicit
     * scheme's stability limit.
     */
    virtual double
    stiffness_bound(const double mass, const double V0) const = 0;

    /// For the log: the law's constants and where the contact acts.
    virtual std::string
    description() const = 0;

    /// A warning for the log if the contact acts away from the impact
    /// point (empty if not).
    virtual std::string
    warning() const = 0;

    /// The model's constants for summary.txt.
    virtual ContactConstants
    constants() const = 0;

    /// Enlarge the set of contact DoFs (after candidates_exhausted);
    /// false if it cannot grow.  Collective.
    virtual bool
    grow_candidates()
    {
      return false;
    }

    /// For the VTU output of a contact with several nodes: their
    /// undeformed positions (m) and tributary areas (m^2); empty for a
    /// point contact.
    virtual std::vector<Point<3>>
    contact_points() const
    {
      return {};
    }
    virtual std::vector<double>
    contact_areas() const
    {
      return {};
    }

    /// The contact DoFs are ordered so that the contact is expected to
    /// reach only the first n_likely_active() of them (a resolved
    /// contact's candidates by their distance from the impact point): the
    /// memory estimate counts the unit responses of these.
    virtual std::size_t
    n_likely_active() const
    {
      return contact_dofs().size();
    }

    /// Whether solve_implicit() asks for the compliance's columns as it
    /// needs them (the resolved contact: its active set reaches a third
    /// of its candidates, which are sorted by distance), so that a time
    /// stepper computes them, and their unit responses, on demand.
    virtual bool
    compliance_on_demand() const
    {
      return false;
    }
    /// DoFs to be given no mass (the modified mass method; empty: the
    /// consistent mass matrix unchanged).
    virtual std::vector<types::global_dof_index>
    massless_dofs() const
    {
      return {};
    }

    /// The layout of save()'s checkpoint section.
    static constexpr std::uint32_t checkpoint_version = 1;

    /// A model's own state between steps (the resolved contact's active
    /// set), for a checkpoint; restored after the stepper's load(), which
    /// regrows the candidate set.
    virtual void
    save(CheckpointWriter &) const
    {}
    virtual void
    load(CheckpointReader &)
    {}

    /// Whether the state's n_active, contact_radius and max_pressure are
    /// meaningful (history columns are added for them).
    virtual bool
    reports_contact_area() const
    {
      return false;
    }
  };



  /**
   * Subsection "Contact", the model part (the Hertz law's constants are
   * HertzContactLaw::Parameters, in the same subsection): which contact
   * model couples the ball and the plate.
   */
  struct ContactModelParameters
  {
    enum class Model
    {
      /// The paper's Eq. 3.14: Hertz law, point force at one node.
      hertz_node,
      /// The same law, alpha measured from the mid-plane under the ball.
      hertz_midplane,
      /// Rigid sphere, unilateral contact at every top node near the
      /// impact point (ResolvedSphereContact).
      resolved_sphere
    };
    Model model = Model::hertz_node;
    /// The names of Contact/Model.
    static const SelectionTable<Model> &
    model_names();
    /// resolved sphere: the sphere's exact profile or the paraboloid.
    bool paraboloid_gap = false;
    /// resolved sphere: the candidates' z DoFs massless (modified mass).
    bool modified_mass = true;
    /// resolved sphere: candidate nodes within this distance (m) of the
    /// impact point; 0: automatic, 1.5 times the half-space estimate of
    /// the largest contact radius plus two of the smallest cells.
    double candidate_radius = 0;

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);
  };



  /**
   * The factory: the model named in the parameters.  expected_radius (m)
   * is the half-space estimate of the largest contact radius
   * (hertz_impact_contact_radius()), reference_modulus (Pa) the top
   * face's E/(1 - nu^2), ball_modulus (Pa) the impactor's E_i/(1 - nu_i^2)
   * (Impactor::indentation_modulus(), infinite for a rigid ball; the
   * Hertz models take it from their law).  Collective.
   */
  std::unique_ptr<ContactModel>
  create_contact_model(const ContactModelParameters &parameters,
                       const HertzContactLaw        &law,
                       const PlateModel             &plate,
                       const double                  sphere_radius,
                       const Point<2>               &impact_point,
                       const double                  expected_radius,
                       const double                  reference_modulus,
                       const double                  ball_modulus);



  /**
   * The paper's model (Eqs. 2.2-2.10, 3.14): the modified Hertz force
   * F = beta K_h alpha_+^{3/2} as a point force at the top-face node
   * nearest to the impact point, alpha = w_ball - W(node).  The implicit
   * step solves alpha + (c_b + chi) F(alpha) = w_free - W_free by Newton's
   * method (chi = C_00), exactly the monolithic Newton's iterates
   * (doc/theory.md, section 7).
   */
  class HertzNodeContact : public ContactModel
  {
  public:
    /// Throws ExcMessage naming Impactor/Impact point if the node lies on
    /// a supported face.  Collective.
    HertzNodeContact(const HertzContactLaw &law,
                     const PlateModel      &plate,
                     const Point<2>        &impact_point);

    const std::vector<types::global_dof_index> &
    contact_dofs() const override
    {
      return dofs;
    }

    void
    solve_implicit(const Vector<double>     &u_free,
                   const FullMatrix<double> &C,
                   const ColumnRequest      &columns,
                   const double              w_free,
                   const double              c_b,
                   const NewtonControl      &newton,
                   ContactState             &state) const override;

    void
    evaluate_explicit(const Vector<double> &u_c,
                      const double          w,
                      ContactState         &state) const override;

    double
    potential(const ContactState &state) const override;

    double
    stiffness_bound(const double mass, const double V0) const override;

    std::string
    description() const override;

    std::string
    warning() const override;

    ContactConstants
    constants() const override;

  private:
    const HertzContactLaw               &law;
    std::vector<types::global_dof_index> dofs;
    Point<3>                             node;
    double                               node_offset = 0; // m
    unsigned int                         node_owner  = 0; // MPI rank
    bool                                 node_offset_note_needed = true;
    /// The modelled part's share of the plate (PlateGeometry::share()):
    /// the node carries this share of the whole plate's Hertz force.
    double share = 1;
  };


  /**
   * The modified Hertz law with the indentation of the plate theories of
   * the impact literature: alpha = w_ball - W_mid, W_mid the deflection of
   * the mid-plane vertex under the impact point, so alpha no longer holds
   * the loaded node's crater.  The force acts as a point force at the top
   * node (as in the paper), whose mid-plane response converges under
   * refinement.  Contact DoFs: {top node z, mid-plane node z}, the force
   * on the first; the implicit step is the Hertz node's scalar Newton with
   * s = c_b + C_mid,top and alpha~ = w_free + u_free,mid.
   */
  class HertzMidplaneContact : public ContactModel
  {
  public:
    /// Throws naming Geometry/Subdivisions z if no vertex lies on the
    /// mid-plane under the impact point.  Collective.
    HertzMidplaneContact(const HertzContactLaw &law,
                         const PlateModel      &plate,
                         const Point<2>        &impact_point);

    const std::vector<types::global_dof_index> &
    contact_dofs() const override
    {
      return dofs;
    }

    void
    solve_implicit(const Vector<double>     &u_free,
                   const FullMatrix<double> &C,
                   const ColumnRequest      &columns,
                   const double              w_free,
                   const double              c_b,
                   const NewtonControl      &newton,
                   ContactState             &state) const override;

    void
    evaluate_explicit(const Vector<double> &u_c,
                      const double          w,
                      ContactState         &state) const override;

    /// The force acts at the top node, alpha is measured at the
    /// mid-plane: no potential.
    bool
    has_potential() const override
    {
      return false;
    }

    double
    potential(const ContactState &state) const override;

    double
    stiffness_bound(const double mass, const double V0) const override;

    std::string
    description() const override;

    std::string
    warning() const override;

    ContactConstants
    constants() const override;

  private:
    const HertzContactLaw               &law;
    const HertzNodeContact               node_contact; // the top node
    std::vector<types::global_dof_index> dofs;
    Point<3>                             mid_node;
    double                               share = 1; // of the whole force
  };
} // namespace fgimpact

#endif
