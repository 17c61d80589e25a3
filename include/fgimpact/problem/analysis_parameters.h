#ifndef fgimpact_problem_analysis_parameters_h
#define fgimpact_problem_analysis_parameters_h

#include <deal.II/base/parameter_handler.h>

namespace fgimpact
{
  using namespace dealii;

  /// Subsection "Static": the load of a static analysis (StaticAnalysis).
  struct StaticAnalysisParameters
  {
    enum class Load
    {
      sinusoidal,
      uniform,
      point,
      sphere
    };


    Load   load        = Load::sinusoidal;
    double pressure    = 1e6;  // q0, Pa
    double point_force = 1e3;  // P, N
    double indentation = 1e-5; // delta of Load = sphere, m
    /// Load = sphere with plasticity: load steps to the indentation
    /// (and as many back to none).
    unsigned int load_steps = 20;

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);
  };



  /// Subsection "Modal": the modes a modal analysis computes
  /// (ModalAnalysis).
  struct ModalAnalysisParameters
  {
    unsigned int n_modes        = 6;
    double       shift          = 0.;    // Hz
    double       tolerance      = 1e-10; // relative change of omega^2
    unsigned int max_iterations = 200;

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);
  };
} // namespace fgimpact

#endif
