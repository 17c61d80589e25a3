#ifndef fgimpact_plate_response_h
#define fgimpact_plate_response_h

#include <deal.II/base/types.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <fgimpact/contact/contact_model.h>

#include <vector>

namespace fgimpact
{
  using namespace dealii;

  /**
   * The plate's side of one coupled impact step, as the ContactCoupler
   * drives it: the plate knows nothing of the ball or of the contact law,
   * only the forces lambda_j at its contact DoFs (N, pushing the plate
   * down).  A step t_n -> t_{n+1} is
   *
   *   u_free = predict()                  the plate without this step's
   *                                       contact forces, at the contact DoFs
   *   lambda = contact solve (u_free - C lambda, the ball's own response)
   *   correct(lambda)                     the plate at t_{n+1}
   *
   * with the compliance C = compliance() (m/N): u_c = u_free - C lambda.
   * Implementations: implicit Newmark and central difference on the finite
   * element plate (TimeStepper, which also carries the fields) and the
   * convolution with the plate's unit response (ImpactStudyEngine).
   *
   * A nonlinear plate (plasticity) fits without a change elsewhere:
   * correct() returns false when the plate's step has not converged with
   * these forces; it has then updated its linearization (the plastic
   * correction in predict(), and C if it changed), and the coupler solves
   * the contact again from predict() until correct() accepts.
   */
  class PlateResponse
  {
  public:
    virtual ~PlateResponse() = default;

    /// The time step (s).
    virtual double
    time_step() const = 0;

    /**
     * Whether the contact forces of a step act at positions that do not
     * depend on them (the explicit scheme: predict() gives u_c at t_{n+1},
     * C = 0, and the ball moves explicitly too).  Otherwise the forces are
     * implicit and the ball follows the same Newmark rule as the plate
     * (newmark(); the block elimination is then exact, doc/theory.md,
     * section 7).
     */
    virtual bool
    explicit_contact() const
    {
      return false;
    }

    /**
     * Start (or, after correct() returned false or the contact set grew,
     * repeat) step `step` at t (s; both label errors): the plate's z
     * displacement (m, positive up) at the contact DoFs without this
     * step's contact forces.  `previous`: the last forces known (a warm
     * start for an iterative solver).  Collective.
     */
    virtual Vector<double>
    predict(const unsigned int  step,
            const double        t,
            const ContactState &previous) = 0;

    /// C_ij (m/N) at the contact DoFs, valid after predict(): its first
    /// require_compliance() columns.
    virtual const FullMatrix<double> &
    compliance() const = 0;

    /// Make compliance()'s first n columns valid (for a contact model
    /// that asks for them, ContactModel::compliance_on_demand()); returns
    /// how many are valid, at least n.  Collective: every rank asks the
    /// same (the contact problem is solved alike on all).  Default: all
    /// columns are always valid.
    virtual unsigned int
    require_compliance(const unsigned int n)
    {
      (void)n;
      return compliance().n();
    }

    /**
     * Finish the step with the contact forces contact.forces (N): the
     * plate at t_{n+1}, its energies.  Returns whether the step is done
     * (always for a linear plate).  Throws ExcMessage naming the step if
     * the solution is not finite.  Collective.
     */
    virtual bool
    correct(const unsigned int  step,
            const double        t,
            const ContactState &contact) = 0;

    /**
     * The contact DoFs changed (the resolved contact's candidate set
     * grew): their compliance, and for the modified mass method the DoFs
     * without mass.  Called before the step is repeated and when a
     * checkpoint's grown set is restored.  Collective.
     */
    virtual void
    set_contact_dofs(const std::vector<types::global_dof_index> &dofs,
                     const std::vector<types::global_dof_index> &massless)
    {
      (void)dofs;
      (void)massless;
      AssertThrow(false,
                  ExcMessage("this plate response has a fixed set "
                             "of contact DoFs"));
    }

    /// Kinetic energy 1/2 v^T M v and strain energy of the plate (J) at
    /// the current time.
    virtual double
    kinetic_energy() const = 0;
    virtual double
    strain_energy() const = 0;
  };
} // namespace fgimpact

#endif
