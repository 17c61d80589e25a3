#include <fgimpact/base/parameter_table.h>
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


  namespace
  {
    /// The entries of StaticAnalysisParameters that set a member as they stand.
    const ParameterTable<StaticAnalysisParameters> &
    static_table()
    {
      using P                              = StaticAnalysisParameters;
      static const ParameterTable<P> table = [] {
        ParameterTable<P> t;
        t.add("Load",
              &P::load,
              load_names(),
              "Load on the top face, downward: sinusoidal = "
              "q0 sin(pi x/a) sin(pi y/b) (exact 3D solution exists "
              "for simply supported plates), uniform = q0, point = "
              "a force P at the top node nearest to the impact "
              "point, sphere = the rigid impactor (Impactor/Radius) "
              "pressed Indentation deep at the impact point, in "
              "frictionless unilateral contact (as Contact/Model = "
              "resolved sphere; refine with Geometry/Contact "
              "refinement levels).");
        t.add("Indentation",
              &P::indentation,
              Patterns::Double(0., 1.),
              "Load = sphere: how far the sphere's lowest point is "
              "pushed below the undeformed top face. Unit: m.");
        t.add("Load steps",
              &P::load_steps,
              Patterns::Integer(1, 100000),
              "Load = sphere with Material/Plasticity = J2: the "
              "indentation is applied in this many equal steps, "
              "and removed in as many (the residual crater is "
              "measured after unloading; load_curve.csv holds "
              "every step).");
        t.add("Pressure",
              &P::pressure,
              Patterns::Double(-1e12, 1e12),
              "Amplitude q0 of the sinusoidal or uniform pressure. "
              "Unit: Pa.");
        t.add("Point force",
              &P::point_force,
              Patterns::Double(-1e12, 1e12),
              "Point force P of Load = point. Unit: N.");
        return t;
      }();
      return table;
    }
  } // namespace



  namespace
  {
    /// The entries of ModalAnalysisParameters that set a member as they stand.
    const ParameterTable<ModalAnalysisParameters> &
    modal_table()
    {
      using P                              = ModalAnalysisParameters;
      static const ParameterTable<P> table = [] {
        ParameterTable<P> t;
        t.add("Number of modes",
              &P::n_modes,
              Patterns::Integer(1, 500),
              "How many of the lowest natural frequencies (above "
              "the shift) to compute.");
        t.add("Shift",
              &P::shift,
              Patterns::Double(0., 1e9),
              "Shift sigma of shift-invert, as a frequency; the "
              "modes nearest above it converge first. 0 needs a "
              "supported plate (K positive definite). Unit: Hz.");
        t.add("Tolerance",
              &P::tolerance,
              Patterns::Double(1e-15, 1e-2),
              "Stop when the relative change of every requested "
              "omega^2 between two iterations is below this. "
              "Dimensionless.");
        t.add("Max iterations",
              &P::max_iterations,
              Patterns::Integer(1, 100000),
              "Subspace iterations cap; reaching it is an error.");
        return t;
      }();
      return table;
    }
  } // namespace



  void
  StaticAnalysisParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Static");
    {
      static_table().declare(prm);
    }
    prm.leave_subsection();
  }



  void
  StaticAnalysisParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Static");
    {
      static_table().parse(prm, *this);
    }
    prm.leave_subsection();
  }



  void
  ModalAnalysisParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Modal");
    {
      modal_table().declare(prm);
    }
    prm.leave_subsection();
  }



  void
  ModalAnalysisParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Modal");
    {
      modal_table().parse(prm, *this);
    }
    prm.leave_subsection();
  }
} // namespace fgimpact
