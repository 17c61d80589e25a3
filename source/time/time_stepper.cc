// The time schemes' registry and factory, and the state every scheme
// checkpoints (time_stepper.h).

#include <fgimpact/base/patterns.h>
#include <fgimpact/time/time_stepper.h>

namespace fgimpact
{
  namespace
  {
    /// What a scheme's factory may read (create_time_stepper()'s
    /// arguments).
    struct TimeStepperInputs
    {
      const TimeStepper::Parameters           &parameters;
      const EffectiveMatrixSolver::Parameters &solver;
      const PlateModel                        &plate;
      const ContactModel                      &contact;
      double                                   impactor_mass;
      double                                   impact_velocity;
    };

    using TimeStepperFactory =
      std::unique_ptr<TimeStepper> (*)(const TimeStepperInputs &);
    using Scheme = TimeStepper::Scheme;

    const Registry<Scheme, TimeStepperFactory> &
    scheme_registry();

  } // namespace



  void
  TimeStepper::save(CheckpointWriter &out) const
  {
    out.put(u);
    out.put(v);
    out.put(kinetic);
    out.put(strain);
    out.put(last_linear_iterations);
  }



  void
  TimeStepper::load(CheckpointReader &in)
  {
    in.get(u);
    in.get(v);
    in.get(kinetic);
    in.get(strain);
    in.get(last_linear_iterations);
  }



  namespace
  {
    /// Every time scheme: name, value, help, factory.  A new scheme is its
    /// class and one row here (and its enum value).
    const Registry<Scheme, TimeStepperFactory> &
    scheme_registry()
    {
      static const Registry<Scheme, TimeStepperFactory> registry = {
        {"implicit",
         Scheme::implicit_newmark,
         "Newmark with 'Newmark beta/gamma' and a Newton iteration on the "
         "contact (block-eliminated: one linear solve per step).",
         [](const TimeStepperInputs &in) -> std::unique_ptr<TimeStepper> {
           return create_implicit_newmark_stepper(in.parameters,
                                                  in.solver,
                                                  in.plate,
                                                  in.contact);
         }},
        {"explicit",
         Scheme::central_difference,
         "central difference (beta = 0, gamma = 1/2) with a row-sum lumped "
         "mass; one matrix-vector product per step, time step limited by "
         "stability.",
         [](const TimeStepperInputs &in) -> std::unique_ptr<TimeStepper> {
           return create_central_difference_stepper(
             in.parameters,
             in.plate,
             in.contact.contact_dofs(),
             in.contact.stiffness_bound(in.impactor_mass, in.impact_velocity));
         }}};
      return registry;
    }
  } // namespace



  const SelectionTable<TimeStepper::Scheme> &
  TimeStepper::scheme_names()
  {
    return scheme_registry();
  }



  std::string
  TimeStepper::scheme_help()
  {
    return scheme_registry().help();
  }



  std::unique_ptr<TimeStepper>
  create_time_stepper(const TimeStepper::Parameters           &parameters,
                      const EffectiveMatrixSolver::Parameters &solver,
                      const PlateModel                        &plate,
                      const ContactModel                      &contact,
                      const double                             impactor_mass,
                      const double                             impact_velocity)
  {
    return scheme_registry().factory(parameters.scheme)(
      {parameters, solver, plate, contact, impactor_mass, impact_velocity});
  }
} // namespace fgimpact
