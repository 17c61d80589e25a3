// The entries of subsections "Time integration" and "Newton"
// (TimeStepper::Parameters, time_stepper.h).

#include <fgimpact/base/parameter_table.h>
#include <fgimpact/base/patterns.h>
#include <fgimpact/time/time_stepper.h>

#include <cmath>

namespace fgimpact
{
  namespace
  {
    /// Subsection "Newton": the implicit scheme's iteration of the contact.
    const ParameterTable<NewtonControl> &
    newton_table()
    {
      using P                              = NewtonControl;
      static const ParameterTable<P> table = [] {
        ParameterTable<P> t;
        t.add("Tolerance",
              &P::tolerance,
              Patterns::Double(1e-15, 0.1),
              "implicit scheme: Newton stops when the relative "
              "change of the indentation between two iterations is "
              "below this (the paper: 0.1 %). Newton converges "
              "quadratically here, so the error left is about its "
              "square. Dimensionless.");
        t.add("Max iterations",
              &P::max_iterations,
              Patterns::Integer(1, 10000),
              "Iteration cap per time step; reaching it stops the "
              "run with an error naming the step.");
        return t;
      }();
      return table;
    }

    /// Newmark's beta and gamma (in Time integration).
    const ParameterTable<NewmarkIntegrator::Parameters> &
    newmark_table()
    {
      using P                              = NewmarkIntegrator::Parameters;
      static const ParameterTable<P> table = [] {
        ParameterTable<P> t;
        t.add("Newmark beta",
              &P::beta,
              Patterns::Double(1e-6, 0.5),
              "Newmark's beta. 1/4 with gamma = 1/2 is the average "
              "acceleration rule (unconditionally stable, energy "
              "conserving). Dimensionless.");
        t.add("Newmark gamma",
              &P::gamma,
              Patterns::Double(0.5, 1.),
              "Newmark's gamma; values above 1/2 add numerical "
              "damping and make the scheme first order. "
              "Dimensionless.");
        return t;
      }();
      return table;
    }
  } // namespace



  namespace
  {
    /// The entries of TimeStepper::Parameters that set a member as they stand.
    const ParameterTable<TimeStepper::Parameters> &
    time_table()
    {
      using P                              = TimeStepper::Parameters;
      static const ParameterTable<P> table = [] {
        ParameterTable<P> t;
        t.add("Scheme",
              &P::scheme,
              TimeStepper::scheme_names(),
              TimeStepper::scheme_help());
        t.add(
          "Stable step safety factor",
          &P::safety_factor,
          Patterns::Double(0.01, 1.),
          "explicit scheme: the automatic time step (Time step = 0) is this "
          "factor times the estimated stability limit 2/omega_max. "
          "Dimensionless.");
        t.add("Time step",
              &P::time_step,
              Patterns::Double(0., 1.),
              "Time step dt; 0 = automatic, the explicit scheme's "
              "stability limit times the safety factor (explicit "
              "only). Unit: s.");
        return t;
      }();
      return table;
    }
  } // namespace



  void
  TimeStepper::Parameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Time integration");
    {
      time_table().declare(prm);
      newmark_table().declare(prm);

      const Parameters defaults;
      prm.declare_entry(
        "End time",
        defaults.auto_end_time ? std::string("auto") :
                                 prm_string(defaults.end_time),
        DoubleOrAuto(1e-12, 1e3),
        "Simulated time span. auto = stop once the ball has left the plate "
        "for good: it moves away and its distance exceeds 1.2 times the "
        "largest rise the plate's energy allows under it, sqrt(2 E C) with "
        "the plate's static compliance C at the contact, and a quarter of "
        "the contact's duration has passed since it left; at the latest at "
        "the Maximum end time. Unit: s.");
      prm.declare_entry("Maximum end time",
                        prm_string(defaults.end_time),
                        Patterns::Double(1e-12, 1e3),
                        "End time = auto: the run stops here if the ball has "
                        "not left for good by then (a warning says so). "
                        "Unit: s.");
    }
    prm.leave_subsection();

    prm.enter_subsection("Newton");
    newton_table().declare(prm);
    prm.leave_subsection();
  }



  void
  TimeStepper::Parameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Time integration");
    time_table().parse(prm, *this);
    newmark_table().parse(prm, newmark);
    auto_end_time = (prm.get("End time") == "auto");
    end_time      = auto_end_time ? prm.get_double("Maximum end time") :
                                    prm.get_double("End time");
    prm.leave_subsection();

    prm.enter_subsection("Newton");
    newton_table().parse(prm, newton);
    prm.leave_subsection();
  }



  unsigned int
  TimeStepper::Parameters::n_steps(const double dt) const
  {
    return static_cast<unsigned int>(std::ceil(end_time / dt - 1e-9));
  }
} // namespace fgimpact
