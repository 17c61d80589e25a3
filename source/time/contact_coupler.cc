#include <fgimpact/time/contact_coupler.h>

#include <cmath>
#include <iostream>
#include <sstream>

namespace fgimpact
{
  std::string
  time_step_label(const unsigned int step, const double t)
  {
    std::ostringstream s;
    s << "time step " << step << " (t = " << t * 1e6 << " us)";
    return s.str();
  }



  void
  check_contact_converged(const ContactState  &state,
                          const unsigned int   step,
                          const double         t,
                          const NewtonControl &newton)
  {
    // The resolved contact's LCP: its iteration counts are not
    // Newton/Max iterations.
    AssertThrow(state.newton_iterations != numbers::invalid_unsigned_int ||
                  !state.used_lcp_fallback,
                ExcMessage("the contact's complementarity problem (active "
                           "set, then projected Gauss-Seidel) was not solved "
                           "at " +
                           time_step_label(step, t) +
                           "; reduce Time integration/Time step."));
    AssertThrow(state.newton_iterations != numbers::invalid_unsigned_int,
                ExcMessage("Newton for the contact did not converge at " +
                           time_step_label(step, t) + " within " +
                           std::to_string(newton.max_iterations) +
                           " iterations; reduce Time integration/Time step or "
                           "raise Newton/Max iterations."));
  }



  ContactCoupler::ContactCoupler(PlateResponse                       &plate,
                                 ContactModel                        &contact,
                                 const NewmarkIntegrator::Parameters &newmark,
                                 const double                         ball_mass,
                                 const NewtonControl                 &newton,
                                 const MPI_Comm                       comm)
    : plate(plate)
    , contact_model(contact)
    , newmark(newmark, plate.time_step())
    , m(ball_mass)
    , newton(newton)
    , comm(comm)
  {}



  void
  ContactCoupler::advance(const unsigned int step,
                          const double       t,
                          ImpactorState     &ball,
                          ContactState      &contact)
  {
    if (plate.explicit_contact())
      {
        advance_explicit(step, t, ball, contact);
        return;
      }
    // The ball: m a0 w = m r_p - F  =>  w = w~ - F/(m a0).
    const double a0      = newmark.mass_factor();
    const double w_tilde = newmark.predictor(ball.w, ball.v, ball.a) / a0;
    for (unsigned int iteration = 0;; ++iteration)
      {
        // The only communication of the contact problem: u_free at the
        // contact DoFs (one all-reduce of m values, in predict()).
        const Vector<double> u_free = plate.predict(step, t, contact);
        contact_model.solve_implicit(
          u_free,
          plate.compliance(),
          [this](const unsigned int n) { return plate.require_compliance(n); },
          w_tilde,
          1. / (m * a0),
          newton,
          contact);
        if (contact.candidates_exhausted)
          {
            // Nothing of the state has changed yet: grow and repeat.
            grow_contact(step, t);
            contact = ContactState();
            continue;
          }
        check_contact_converged(contact, step, t, newton);
        if (plate.correct(step, t, contact))
          break;
        AssertThrow(iteration + 1 < max_plate_iterations,
                    ExcMessage("the plate's step did not converge with the "
                               "contact at " +
                               time_step_label(step, t) + " within " +
                               std::to_string(max_plate_iterations) +
                               " iterations; reduce Time integration/Time "
                               "step."));
      }
    newmark.update(w_tilde - contact.force / (m * a0), ball.w, ball.v, ball.a);
  }



  void
  ContactCoupler::advance_explicit(const unsigned int step,
                                   const double       t,
                                   ImpactorState     &ball,
                                   ContactState      &contact)
  {
    // Velocity Verlet: positions, the forces there, accelerations.
    const double         dt  = plate.time_step();
    const Vector<double> u_c = plate.predict(step, t, contact);
    ball.w += dt * ball.v + 0.5 * dt * dt * ball.a;
    ball.v += 0.5 * dt * ball.a;
    contact_model.evaluate_explicit(u_c, ball.w, contact);
    plate.correct(step, t, contact);
    ball.a = -contact.force / m;
    ball.v += 0.5 * dt * ball.a;
  }



  void
  ContactCoupler::grow_contact(const unsigned int step, const double t)
  {
    AssertThrow(contact_model.grow_candidates(),
                ExcMessage("the contact reached the edge of the candidate set "
                           "at " +
                           time_step_label(step, t) +
                           ", which cannot grow beyond the sphere's radius: "
                           "the elements under the ball are too coarse for "
                           "the resolved contact; raise Geometry/Contact "
                           "refinement levels (auto chooses them from the "
                           "scene)."));
    plate.set_contact_dofs(contact_model.contact_dofs(),
                           contact_model.massless_dofs());
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      std::cout << "  " << time_step_label(step, t)
                << ": the contact reached the edge of the candidate set; "
                   "grown to "
                << contact_model.contact_dofs().size() << " candidates"
                << std::endl;
  }



  void
  ContactCoupler::save(CheckpointWriter &out) const
  {
    out.put<std::uint64_t>(contact_model.contact_dofs().size());
  }



  void
  ContactCoupler::load(CheckpointReader &in)
  {
    std::uint64_t n_contact_dofs = 0;
    in.get(n_contact_dofs);
    if (n_contact_dofs == contact_model.contact_dofs().size())
      return;
    // The candidate set had grown: grow it alike.
    while (contact_model.contact_dofs().size() < n_contact_dofs)
      AssertThrow(contact_model.grow_candidates(),
                  ExcMessage("the checkpoint's contact candidate set cannot "
                             "be rebuilt"));
    AssertThrow(contact_model.contact_dofs().size() == n_contact_dofs,
                ExcMessage("the checkpoint's contact candidate set does not "
                           "match this set-up"));
    plate.set_contact_dofs(contact_model.contact_dofs(),
                           contact_model.massless_dofs());
  }
} // namespace fgimpact
