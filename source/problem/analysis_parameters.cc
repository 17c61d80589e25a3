#include <fgimpact/base/selection.h>
#include <fgimpact/problem/analysis_parameters.h>

namespace fgimpact
{
  namespace
  {
    /// The names of Static/Load.
    const SelectionTable<StaticAnalysisParameters::Load> &
    load_names()
    {
      using L                              = StaticAnalysisParameters::Load;
      static const SelectionTable<L> names = {{"sinusoidal", L::sinusoidal},
                                              {"uniform", L::uniform},
                                              {"point", L::point},
                                              {"sphere", L::sphere}};
      return names;
    }
  } // namespace


  void
  StaticAnalysisParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Static");
    {
      prm.declare_entry("Load",
                        "sinusoidal",
                        load_names().pattern(),
                        "Load on the top face, downward: sinusoidal = "
                        "q0 sin(pi x/a) sin(pi y/b) (exact 3D solution exists "
                        "for simply supported plates), uniform = q0, point = "
                        "a force P at the top node nearest to the impact "
                        "point, sphere = the rigid impactor (Impactor/Radius) "
                        "pressed Indentation deep at the impact point, in "
                        "frictionless unilateral contact (as Contact/Model = "
                        "resolved sphere; refine with Geometry/Contact "
                        "refinement levels).");
      prm.declare_entry("Indentation",
                        "1e-5",
                        Patterns::Double(0., 1.),
                        "Load = sphere: how far the sphere's lowest point is "
                        "pushed below the undeformed top face. Unit: m.");
      prm.declare_entry("Load steps",
                        "20",
                        Patterns::Integer(1, 100000),
                        "Load = sphere with Material/Plasticity = J2: the "
                        "indentation is applied in this many equal steps, "
                        "and removed in as many (the residual crater is "
                        "measured after unloading; load_curve.csv holds "
                        "every step).");
      prm.declare_entry("Pressure",
                        "1e6",
                        Patterns::Double(-1e12, 1e12),
                        "Amplitude q0 of the sinusoidal or uniform pressure. "
                        "Unit: Pa.");
      prm.declare_entry("Point force",
                        "1000",
                        Patterns::Double(-1e12, 1e12),
                        "Point force P of Load = point. Unit: N.");
    }
    prm.leave_subsection();
  }



  void
  StaticAnalysisParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Static");
    {
      load        = load_names().value(prm.get("Load"));
      indentation = prm.get_double("Indentation");
      load_steps  = prm.get_integer("Load steps");
      pressure    = prm.get_double("Pressure");
      point_force = prm.get_double("Point force");
    }
    prm.leave_subsection();
  }



  void
  ModalAnalysisParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Modal");
    {
      prm.declare_entry("Number of modes",
                        "6",
                        Patterns::Integer(1, 500),
                        "How many of the lowest natural frequencies (above "
                        "the shift) to compute.");
      prm.declare_entry("Shift",
                        "0",
                        Patterns::Double(0., 1e9),
                        "Shift sigma of shift-invert, as a frequency; the "
                        "modes nearest above it converge first. 0 needs a "
                        "supported plate (K positive definite). Unit: Hz.");
      prm.declare_entry("Tolerance",
                        "1e-10",
                        Patterns::Double(1e-15, 1e-2),
                        "Stop when the relative change of every requested "
                        "omega^2 between two iterations is below this. "
                        "Dimensionless.");
      prm.declare_entry("Max iterations",
                        "200",
                        Patterns::Integer(1, 100000),
                        "Subspace iterations cap; reaching it is an error.");
    }
    prm.leave_subsection();
  }



  void
  ModalAnalysisParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Modal");
    {
      n_modes        = prm.get_integer("Number of modes");
      shift          = prm.get_double("Shift");
      tolerance      = prm.get_double("Tolerance");
      max_iterations = prm.get_integer("Max iterations");
    }
    prm.leave_subsection();
  }
} // namespace fgimpact
