#include <deal.II/base/exceptions.h>

#include <fgimpact/parameters.h>

#include <string>

namespace fgimpact
{
  void
  Parameters::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Problem type",
                      "impact",
                      Patterns::Selection("impact|static|modal"),
                      "impact: the sphere strikes the plate (time history). "
                      "static: K u = f under the load of subsection Static. "
                      "modal: the lowest natural frequencies and mode "
                      "shapes (subsection Modal).");
    AccuracyPreset::Parameters::declare_parameters(prm);
    PlateGeometry::Parameters::declare_parameters(prm);
    StaticAnalysis::Parameters::declare_parameters(prm);
    ModalAnalysis::Parameters::declare_parameters(prm);
    FunctionallyGradedMaterial::Parameters::declare_parameters(prm);
    HertzContactLaw::Parameters::declare_parameters(prm);
    ContactModelParameters::declare_parameters(prm);
    Impactor::Parameters::declare_parameters(prm);
    PlateModel::Parameters::declare_parameters(prm);
    EffectiveMatrixSolver::Parameters::declare_parameters(prm);
    TimeStepper::Parameters::declare_parameters(prm);
    OutputParameters::declare_parameters(prm);
  }



  void
  Parameters::parse_parameters(ParameterHandler &prm)
  {
    const std::string type = prm.get("Problem type");
    problem_type           = (type == "static" ? ProblemType::static_load :
                              type == "modal"  ? ProblemType::modal :
                                                 ProblemType::impact);
    // First, explicitly: a preset rewrites Geometry/Subdivisions and Time
    // integration/Time step in prm (so parameters.prm shows them).
    accuracy.apply(prm);

    geometry.parse_parameters(prm);
    material.parse_parameters(prm);
    finite_element.parse_parameters(prm);
    contact.parse_parameters(prm);
    contact_model.parse_parameters(prm);
    impactor.parse_parameters(prm);
    time_integration.parse_parameters(prm);
    linear_solver.parse_parameters(prm);
    static_analysis.parse_parameters(prm);
    modal.parse_parameters(prm);
    output.parse_parameters(prm);
  }



  void
  Parameters::validate() const
  {
    const double   a = geometry.length, b = geometry.width;
    const Impactor impactor_object(impactor);
    const Point<2> p = impactor_object.impact_point(a, b);
    AssertThrow(p[0] > 0 && p[0] < a,
                ExcMessage("Impactor/Impact point x = " + std::to_string(p[0]) +
                           " m lies outside the open interval (0, a = " +
                           std::to_string(a) + " m)."));
    AssertThrow(p[1] > 0 && p[1] < b,
                ExcMessage("Impactor/Impact point y = " + std::to_string(p[1]) +
                           " m lies outside the open interval (0, b = " +
                           std::to_string(b) + " m)."));
    const TimeStepper::Parameters &ti = time_integration;
    const bool                     explicit_scheme =
      (ti.scheme == TimeStepper::Scheme::central_difference);
    AssertThrow(ti.time_step > 0 || explicit_scheme,
                ExcMessage("Time integration/Time step = 0 (automatic) is "
                           "only available with Scheme = explicit."));
    AssertThrow(ti.end_time >= ti.time_step,
                ExcMessage("Time integration/End time is shorter than one "
                           "Time step."));
    AssertThrow(ti.time_step == 0 || ti.end_time / ti.time_step < 1e8,
                ExcMessage("Time integration/End time divided by Time step "
                           "exceeds 1e8 steps."));
    AssertThrow(explicit_scheme ||
                  ti.newmark.beta >= ti.newmark.gamma / 4. - 1e-14,
                ExcMessage("Time integration/Newmark beta must be at least "
                           "gamma/4 for the unconditionally stable implicit "
                           "scheme (beta = 1/4, gamma = 1/2 is the default)."));
    AssertThrow(!(explicit_scheme &&
                  contact_model.model ==
                    ContactModelParameters::Model::resolved_sphere),
                ExcMessage("Contact/Model = resolved sphere needs Time "
                           "integration/Scheme = implicit: its contact is "
                           "rigid, which no explicit step is stable for."));
    AssertThrow(output.directory.find_first_not_of(" \t") != std::string::npos,
                ExcMessage("Output/Directory is empty."));
  }
} // namespace fgimpact
