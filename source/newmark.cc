#include <deal.II/base/exceptions.h>

#include <fgimpact/newmark.h>

#include <cmath>

namespace fgimpact
{
  void
  NewmarkIntegrator::Parameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Time integration");
    {
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
      prm.declare_entry("End time",
                        "400e-6",
                        Patterns::Double(1e-12, 1e3),
                        "Simulated time span. Unit: s.");
    }
    prm.leave_subsection();
  }



  void
  NewmarkIntegrator::Parameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Time integration");
    {
      beta      = prm.get_double("Newmark beta");
      gamma     = prm.get_double("Newmark gamma");
      time_step = prm.get_double("Time step");
      end_time  = prm.get_double("End time");
    }
    prm.leave_subsection();
  }



  NewmarkIntegrator::NewmarkIntegrator(const Parameters &parameters)
    : parameters(parameters)
    , dt(parameters.time_step)
    , a0(1. / (parameters.beta * dt * dt))
    , a1(1. / (parameters.beta * dt))
    , a2(1. / (2. * parameters.beta) - 1.)
  {}



  unsigned int
  NewmarkIntegrator::number_of_steps(const double end_time, const double dt)
  {
    return static_cast<unsigned int>(std::ceil(end_time / dt - 1e-9));
  }



  unsigned int
  NewmarkIntegrator::n_steps() const
  {
    return number_of_steps(parameters.end_time, dt);
  }
} // namespace fgimpact
