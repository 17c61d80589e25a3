// The entries of subsections "Time integration" and "Newton"
// (TimeStepper::Parameters, time_stepper.h).

#include <fgimpact/base/patterns.h>
#include <fgimpact/time/time_stepper.h>

#include <cmath>

namespace fgimpact
{
  namespace
  {
    /// Subsection "Newton": the implicit scheme's iteration of the contact.
    void
    declare_newton(ParameterHandler &prm)
    {
      prm.enter_subsection("Newton");
      {
        prm.declare_entry("Tolerance",
                          "1e-3",
                          Patterns::Double(1e-15, 0.1),
                          "implicit scheme: Newton stops when the relative "
                          "change of the indentation between two iterations is "
                          "below this (the paper: 0.1 %). Newton converges "
                          "quadratically here, so the error left is about its "
                          "square. Dimensionless.");
        prm.declare_entry("Max iterations",
                          "50",
                          Patterns::Integer(1, 10000),
                          "Iteration cap per time step; reaching it stops the "
                          "run with an error naming the step.");
      }
      prm.leave_subsection();
    }
  } // namespace



  void
  TimeStepper::Parameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Time integration");
    {
      prm.declare_entry("Scheme",
                        "implicit",
                        scheme_names().pattern(),
                        TimeStepper::scheme_help());
      prm.declare_entry(
        "Stable step safety factor",
        "0.9",
        Patterns::Double(0.01, 1.),
        "explicit scheme: the automatic time step (Time step = 0) is this "
        "factor times the estimated stability limit 2/omega_max. "
        "Dimensionless.");
      prm.declare_entry("Newmark beta",
                        "0.25",
                        Patterns::Double(1e-6, 0.5),
                        "Newmark's beta. 1/4 with gamma = 1/2 is the average "
                        "acceleration rule (unconditionally stable, energy "
                        "conserving). Dimensionless.");
      prm.declare_entry("Newmark gamma",
                        "0.5",
                        Patterns::Double(0.5, 1.),
                        "Newmark's gamma; values above 1/2 add numerical "
                        "damping and make the scheme first order. "
                        "Dimensionless.");
      prm.declare_entry("Time step",
                        "1e-6",
                        Patterns::Double(0., 1.),
                        "Time step dt; 0 = automatic, the explicit scheme's "
                        "stability limit times the safety factor (explicit "
                        "only). Unit: s.");
      prm.declare_entry(
        "End time",
        "auto",
        DoubleOrAuto(1e-12, 1e3),
        "Simulated time span. auto = stop once the ball has left the plate "
        "for good: it moves away and its distance exceeds 1.2 times the "
        "largest rise the plate's energy allows under it, sqrt(2 E C) with "
        "the plate's static compliance C at the contact, and a quarter of "
        "the contact's duration has passed since it left; at the latest at "
        "the Maximum end time. Unit: s.");
      prm.declare_entry("Maximum end time",
                        "2e-3",
                        Patterns::Double(1e-12, 1e3),
                        "End time = auto: the run stops here if the ball has "
                        "not left for good by then (a warning says so). "
                        "Unit: s.");
    }
    prm.leave_subsection();

    declare_newton(prm);
  }



  void
  TimeStepper::Parameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Time integration");
    scheme        = scheme_names().value(prm.get("Scheme"));
    safety_factor = prm.get_double("Stable step safety factor");
    newmark.beta  = prm.get_double("Newmark beta");
    newmark.gamma = prm.get_double("Newmark gamma");
    time_step     = prm.get_double("Time step");
    auto_end_time = (prm.get("End time") == "auto");
    end_time      = auto_end_time ? prm.get_double("Maximum end time") :
                                    prm.get_double("End time");
    prm.leave_subsection();

    prm.enter_subsection("Newton");
    newton.tolerance      = prm.get_double("Tolerance");
    newton.max_iterations = prm.get_integer("Max iterations");
    prm.leave_subsection();
  }



  unsigned int
  TimeStepper::Parameters::n_steps(const double dt) const
  {
    return static_cast<unsigned int>(std::ceil(end_time / dt - 1e-9));
  }
} // namespace fgimpact
