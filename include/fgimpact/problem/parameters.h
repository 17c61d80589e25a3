#ifndef fgimpact_parameters_h
#define fgimpact_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <fgimpact/contact/contact_law.h>
#include <fgimpact/contact/contact_model.h>
#include <fgimpact/contact/impactor.h>
#include <fgimpact/material/material.h>
#include <fgimpact/material/strength.h>
#include <fgimpact/material/thermal.h>
#include <fgimpact/output/monitor.h>
#include <fgimpact/plate/geometry.h>
#include <fgimpact/plate/linear_solver.h>
#include <fgimpact/plate/plate_model.h>
#include <fgimpact/problem/accuracy_preset.h>
#include <fgimpact/problem/analysis_parameters.h>
#include <fgimpact/time/time_stepper.h>

#include <string>
#include <vector>

namespace fgimpact
{
  using namespace dealii;

  /// What a run computes (entry "Problem type").
  enum class ProblemType
  {
    impact,
    static_load,
    modal
  };

  /**
   * All parameters of a run: one member per component, each of which
   * declares and parses its own subsection (ASPECT's way).  The accuracy
   * preset is applied explicitly before any component parses, so parse
   * order does not matter otherwise.  Physics classes receive their
   * member, never the ParameterHandler.
   */
  struct Parameters
  {
    ProblemType                            problem_type = ProblemType::impact;
    AccuracyPreset::Parameters             accuracy;
    PlateGeometry::Parameters              geometry;
    FunctionallyGradedMaterial::Parameters material;
    ThermalParameters                      thermal;
    GradedStrength::Parameters             strength;
    PlateModel::Parameters                 finite_element;
    HertzContactLaw::Parameters            contact;
    ContactModelParameters                 contact_model;
    Impactor::Parameters                   impactor;
    TimeStepper::Parameters                time_integration;
    EffectiveMatrixSolver::Parameters      linear_solver;
    StaticAnalysisParameters               static_analysis;
    ModalAnalysisParameters                modal;
    OutputParameters                       output;

    static void
    declare_parameters(ParameterHandler &prm);

    /// Apply the accuracy preset to prm, then parse every subsection.
    void
    parse_parameters(ParameterHandler &prm);

    /// Check consistency between entries (one-line messages naming the
    /// parameter); throws ExcMessage.  Refuses a static load or a modal
    /// Shift = 0 on a plate whose supports leave a rigid-body mode free
    /// (a singular stiffness matrix), an impactor wider than the plate and
    /// Newmark parameters outside 2 beta >= gamma >= 1/2.
    void
    validate() const;

    /// Inputs that run but are likely not what was meant (one line each,
    /// naming the parameter): no node under the impact point.
    std::vector<std::string>
    warnings() const;

    /// Whether the ball's contact is resolved (Contact/Model = resolved
    /// sphere in an impact, Static/Load = sphere): its accuracy then
    /// depends on the element size under the ball.
    bool
    uses_resolved_contact() const;
  };
} // namespace fgimpact

#endif
