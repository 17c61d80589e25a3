#ifndef fgimpact_contact_coupler_h
#define fgimpact_contact_coupler_h

#include <deal.II/base/mpi.h>

#include <fgimpact/base/checkpoint.h>
#include <fgimpact/contact/contact_model.h>
#include <fgimpact/time/newmark.h>
#include <fgimpact/time/plate_response.h>

namespace fgimpact
{
  using namespace dealii;

  /// The impactor's scalar unknown: displacement w (m), velocity v (m/s),
  /// acceleration a (m/s^2), positive in the impact direction (-z).
  struct ImpactorState
  {
    double w = 0, v = 0, a = 0;
  };

  /**
   * One coupled impact step, the same for every plate response (implicit
   * Newmark, central difference, the study's convolution) and every
   * contact model: the ball's update, the contact solve, the growth of the
   * resolved contact's candidate set with the step repeated, the
   * iteration with a nonlinear plate, and the failure messages.  The
   * ImpactDriver and the study engine both drive it.
   *
   * Implicit plate: the ball follows Newmark with the plate's rule,
   *   w_{n+1} = w~ - F/(m a0),  w~ = r_n/a0,
   * so the contact model sees u_c = u_free - C lambda and
   * w = w~ - c_b sum lambda, c_b = 1/(m a0).  Explicit plate: velocity
   * Verlet for the ball, the forces at the new positions.
   */
  class ContactCoupler
  {
  public:
    /**
     * plate and contact must outlive the coupler; newmark: the plate's
     * scheme (the ball uses the same rule); ball_mass (kg): the modelled
     * part's share of the impactor's mass; newton: the contact's stopping
     * rule.  Growth messages go to rank 0 of comm's stdout.
     */
    ContactCoupler(PlateResponse                       &plate,
                   ContactModel                        &contact,
                   const NewmarkIntegrator::Parameters &newmark,
                   const double                         ball_mass,
                   const NewtonControl                 &newton,
                   const MPI_Comm                       comm);

    /// Advance ball, contact and plate from t_{n+1} - dt to t (s); `step`
    /// and t label errors.  Collective.
    void
    advance(const unsigned int step,
            const double       t,
            ImpactorState     &ball,
            ContactState      &contact);

    /// The layout of save()'s checkpoint section.
    static constexpr std::uint32_t checkpoint_version = 1;

    /// The contact set's size, for a checkpoint.
    void
    save(CheckpointWriter &out) const;

    /// Restore save()'s contact set (grows the contact model alike and
    /// hands the plate the grown set), before the plate's and the contact
    /// model's own load().  Collective.
    void
    load(CheckpointReader &in);

    /// Most plate/contact iterations of a nonlinear plate in one step.
    static constexpr unsigned int max_plate_iterations = 100;

  private:
    void
    advance_explicit(const unsigned int step,
                     const double       t,
                     ImpactorState     &ball,
                     ContactState      &contact);

    /// The contact reached the candidate set's edge: a larger set, handed
    /// to the plate; throws naming the step if it cannot grow.
    void
    grow_contact(const unsigned int step, const double t);

    PlateResponse          &plate;
    ContactModel           &contact_model;
    const NewmarkIntegrator newmark;
    const double            m;
    const NewtonControl     newton;
    const MPI_Comm          comm;
  };



  /// "time step N (t = T us)", for messages.
  std::string
  time_step_label(const unsigned int step, const double t);

  /// An implicit step's contact solve failed (ContactState::
  /// newton_iterations invalid): throws ExcMessage naming the step and the
  /// parameters to change (for the resolved contact's LCP, whose
  /// iterations are not Newton's, the time step).  No-op if it converged.
  void
  check_contact_converged(const ContactState  &state,
                          const unsigned int   step,
                          const double         t,
                          const NewtonControl &newton);
} // namespace fgimpact

#endif
