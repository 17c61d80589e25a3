#ifndef fgimpact_resolved_contact_h
#define fgimpact_resolved_contact_h

#include <deal.II/base/point.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <fgimpact/contact/contact_model.h>
#include <fgimpact/contact/impactor_profile.h>
#include <fgimpact/plate/plate_model.h>

#include <limits>
#include <string>
#include <vector>

namespace fgimpact
{
  using namespace dealii;

  /// The element sizes across the largest contact radius that the
  /// automatic contact refinement aims at, and below which a finished
  /// resolved run warns (doc/contact.md).
  constexpr double contact_elements_per_radius = 4.;

  /**
   * A sphere (radius R, rigid or elastic) in frictionless unilateral contact
   * with the top face: no contact law, the graded 3D elasticity under the ball
   * is the contact stiffness.  The candidates are the z DoFs of the top-face
   * support points within the candidate radius r_c of the impact point
   * (hanging nodes excluded), sorted by their distance r_j from it, so the
   * first is the node at the impact point.
   *
   * Gap of candidate j, measured vertically (small slopes, see
   * doc/contact.md):
   *
   *   g_j = phi_j - w - u_j >= 0,   phi_j = R - sqrt(R^2 - r_j^2)
   *
   * (w the ball's displacement, positive down; u_j the plate's z
   * displacement, positive up; phi_j the sphere's height above its lowest
   * point, or the paraboloid r_j^2/(2R)).  With the Delassus matrix C
   * (m/N), the ball's rigid-body compliance c_b and, for an elastic ball,
   * its surface compliance H (m/N, ball_compliance()), an implicit step is
   * the LCP
   *
   *   g = q + (C + c_b 1 1^T + H) lambda,  q_j = phi_j - w_free - u_free_j,
   *   lambda >= 0, g >= 0, lambda^T g = 0,
   *
   * solved by solve_lcp() warm-started from the last step's active set.
   * The complementarity holds at the end of every step (exact
   * enforcement; the energy behaviour is measured in doc/contact.md).
   * A node of the outermost ring in contact sets
   * ContactState::candidates_exhausted: the caller grows the set
   * (grow_candidates()) and repeats the step.
   */
  class ResolvedSphereContact : public ContactModel
  {
  public:
    /// The automatic candidate radius is this factor times the expected
    /// contact radius (plus two of the smallest elements); the candidates
    /// within 1/factor of the candidate radius are the likely active ones.
    static constexpr double candidate_radius_factor = 1.5;

    /// Collective.  surface: the gap function (the sphere's exact
    /// profile or the paraboloid, create_sphere_profile()); the candidate
    /// set grows up to its extent().  reference_modulus: the top face's
    /// Q = E/(1 - nu^2) (Pa); ball_modulus: the ball's Q_i (Pa), infinite
    /// for a rigid ball.  Throws if no candidate is found, naming
    /// Contact/Candidate radius.
    ResolvedSphereContact(
      const PlateModel                             &plate,
      const double                                  sphere_radius,
      const Point<2>                               &impact_point,
      const double                                  candidate_radius,
      const std::shared_ptr<const ImpactorProfile> &surface,
      const double                                  reference_modulus,
      const bool                                    massless_candidates = false,
      const double ball_modulus = std::numeric_limits<double>::infinity());

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

    bool
    compliance_on_demand() const override
    {
      return true;
    }

    /// Hertz's E* of plate and ball (Pa).
    double
    contact_modulus() const
    {
      return reference_modulus;
    }

    /// Not available: the explicit scheme is refused with this model.
    void
    evaluate_explicit(const Vector<double> &u_c,
                      const double          w,
                      ContactState         &state) const override;

    /// A rigid unilateral contact stores no energy; an elastic ball the
    /// strain energy of its surface, lambda^T H lambda / 2 (J, the part's).
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

    std::vector<Point<3>>
    contact_points() const override
    {
      return points;
    }

    std::vector<double>
    contact_areas() const override
    {
      return areas;
    }

    /// The candidates within 1/candidate_radius_factor (2/3) of the
    /// candidate radius: the automatic radius is that factor times the
    /// expected contact radius (plus two of the smallest elements).
    std::size_t
    n_likely_active() const override;

    std::vector<types::global_dof_index>
    massless_dofs() const override
    {
      return massless_candidates ? dofs :
                                   std::vector<types::global_dof_index>();
    }

    bool
    reports_contact_area() const override
    {
      return true;
    }

    /// The candidate radius and the active set (the warm start).
    void
    save(CheckpointWriter &out) const override;
    void
    load(CheckpointReader &in) override;

    /// Enlarge the candidate radius 1.5 times (at most to R) and collect
    /// the candidates anew.  Collective.
    bool
    grow_candidates() override;

    /// Distance r_j (m) of each candidate from the impact point.
    const std::vector<double> &
    candidate_radii() const
    {
      return radii;
    }

    /// Tributary top-face area A_j = int N_j dA of each candidate (m^2):
    /// the nodal pressure is lambda_j / A_j.
    const std::vector<double> &
    candidate_areas() const
    {
      return areas;
    }

    /// The elastic ball's surface compliance H (m/N; empty for a rigid
    /// ball): H_ij is the ball's surface displacement (inward, along z) at
    /// candidate i under a unit force at candidate j and at its mirror
    /// images (a symmetric part), from Boussinesq's half-space solution,
    /// 1/(pi Q_i d), and for the candidate's own patch the centre
    /// displacement of a uniform pressure on a disc of its tributary area,
    /// 2/(pi Q_i rho).  Exact in the limit of a contact radius small
    /// against R (Hertz's assumption); doc/contact.md.
    const FullMatrix<double> &
    ball_compliance() const
    {
      return ball_matrix;
    }

    /// The largest r_j (m): the candidate set reaches this far.
    double
    reach() const
    {
      return radii.back();
    }

  private:
    /// Candidates, areas, profile and an empty active set for the
    /// current candidate radius.
    void
    build_candidates();

    void
    collect_candidates(const PlateModel &plate,
                       const Point<2>   &impact_point,
                       const double      candidate_radius);
    void
    compute_areas(const PlateModel &plate);
    /// ball_matrix for the current candidates (nothing for a rigid ball).
    void
    compute_ball_compliance();
    /// The contact's extent at the forces lambda (N) and gaps g (m): the
    /// active nodes, the largest pressure, the contact radius and whether
    /// the candidates are exhausted; returns the smallest gap (m).
    double
    describe_extent(const Vector<double> &lambda,
                    const Vector<double> &g,
                    ContactState         &state) const;
    /// After the LCP A lambda + q >= 0: the gaps, the contact's extent,
    /// the displacement of the first candidate (u_free - C lambda, m) and
    /// the indentation column into state.
    void
    describe_solution(const FullMatrix<double> &A,
                      const Vector<double>     &q,
                      const Vector<double>     &lambda,
                      const Vector<double>     &u_free,
                      const FullMatrix<double> &C,
                      ContactState             &state) const;

    const PlateModel                            &plate;
    const Point<2>                               impact_point;
    const double                                 R;
    const std::shared_ptr<const ImpactorProfile> surface;
    const double                                 reference_modulus; // Pa
    const bool                                   massless_candidates;
    const double                                 ball_modulus;     // Q_i, Pa
    FullMatrix<double>                           ball_matrix;      // H, m/N
    double                                       candidate_radius; // m
    std::vector<types::global_dof_index>         dofs;
    std::vector<double>                          radii, areas, profile;
    std::vector<Point<3>>                        points; // undeformed, m
    /// Symmetric part (Geometry/Symmetry): the part's share of the plate
    /// and how many nodes of the whole plate each candidate stands for.
    double                    share = 1;
    std::vector<unsigned int> multiplicity;
    double                    smallest_spacing = 0; // m
    /// The active set of the last solve (warm start).
    mutable std::vector<bool> active;
    /// solve_implicit()'s LCP matrix C + c_b 1 1^T (+ H), m x m, refilled
    /// every step in C's valid columns (kept to spare the allocation).
    mutable FullMatrix<double> delassus;
  };
} // namespace fgimpact

#endif
