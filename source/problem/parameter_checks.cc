// Checks of the input that span several subsections (called from
// Parameters::check()).

#include <deal.II/base/exceptions.h>

#include <fgimpact/problem/parameter_checks.h>

namespace fgimpact
{
  void
  check_plasticity(const Parameters &p)
  {
    if (p.strength.plasticity != GradedStrength::Plasticity::j2)
      return;
    const std::string name = "Material/Plasticity = J2";
    AssertThrow(p.strength.metal_yield_strength > 0.,
                ExcMessage(name + " needs Material/Metal yield strength > "
                                  "0 (0 switches the yield check off)."));
    if (p.problem_type == ProblemType::impact)
      {
        AssertThrow(p.contact_model.model ==
                      ContactModelParameters::Model::resolved_sphere,
                    ExcMessage(name + " needs Contact/Model = resolved "
                                      "sphere: under a point force (hertz "
                                      "node, hertz midplane) the stress has "
                                      "no converged value, and neither has "
                                      "the plastic zone."));
        AssertThrow(p.time_integration.scheme ==
                      TimeStepper::Scheme::implicit_newmark,
                    ExcMessage(name + " needs Time integration/Scheme = "
                                      "implicit."));
      }
    else
      AssertThrow(p.problem_type == ProblemType::static_load &&
                    p.static_analysis.load ==
                      StaticAnalysisParameters::Load::sphere,
                  ExcMessage(name + " is modelled for impacts and for "
                                    "Static/Load = sphere only; set "
                                    "Material/Plasticity = none for this "
                                    "problem."));
  }



  void
  check_converged_accuracy(const Parameters &p)
  {
    if (p.accuracy.preset != AccuracyPreset::Preset::converged)
      return;
    AssertThrow(p.problem_type == ProblemType::impact,
                ExcMessage("Accuracy = converged is for Problem type = "
                           "impact; use Accuracy = custom."));
    AssertThrow(p.contact_model.model !=
                  ContactModelParameters::Model::hertz_node,
                ExcMessage("Accuracy = converged with Contact/Model = hertz "
                           "node: its point force does not converge under "
                           "refinement; use resolved sphere or hertz "
                           "midplane."));
    AssertThrow(p.time_integration.scheme ==
                  TimeStepper::Scheme::implicit_newmark,
                ExcMessage("Accuracy = converged needs Time "
                           "integration/Scheme = implicit (it halves the "
                           "time step)."));
  }



  void
  check_adaptive_mesh(const Parameters &p)
  {
    AssertThrow(!p.geometry.adaptive_estimate || p.geometry.adaptive_cycles > 0,
                ExcMessage("Geometry/Adaptive refinement estimate = true "
                           "needs Adaptive refinement cycles > 0; set it to "
                           "false or give the cycles."));
    if (p.geometry.adaptive_cycles == 0)
      return;
    const std::string name = "Geometry/Adaptive refinement cycles > 0";
    AssertThrow(p.problem_type == ProblemType::impact,
                ExcMessage(name + " is for Problem type = impact; set it "
                                  "to 0."));
    // Kelly's indicator is largest under a point force, whose displacement
    // has no converged value there (u ~ 1/r): the cycles would refine the
    // singularity, not the plate.
    AssertThrow(p.contact_model.model ==
                  ContactModelParameters::Model::resolved_sphere,
                ExcMessage(name + " needs Contact/Model = resolved sphere "
                                  "(under a point force the indicator "
                                  "refines the singularity); set it to 0."));
    AssertThrow(p.accuracy.preset != AccuracyPreset::Preset::converged,
                ExcMessage(name + " with Accuracy = converged is not "
                                  "offered yet; use one of the two."));
  }



  void
  check_resolved_contact_degree(const Parameters &p)
  {
    // The resolved contact is node to surface: each top-face node carries
    // its own force.  On the quadratic faces of Degree = 2 the nodes'
    // shares of a pressure are 1 : 4 : 16 (corner, mid-side, centre), and
    // which ring is the last in contact at the peak moves the force: on
    // the default scene at contact levels 2-5 it is 3519.2, 3315.9,
    // 3288.7, 3315.7 N, changes of -5.8, -0.82, +0.82 % that stop
    // shrinking (the 8-node brick at the same node spacing, levels 4-6:
    // 3350.8, 3326.0, 3329.7 N).  Converging it needs a mortar
    // (segment-to-segment) contact.
    AssertThrow(!(p.problem_type == ProblemType::impact &&
                  p.contact_model.model ==
                    ContactModelParameters::Model::resolved_sphere &&
                  p.finite_element.degree > 1),
                ExcMessage(
                  "Contact/Model = resolved sphere with Finite element/Degree "
                  "= 2: its node-to-surface contact on quadratic faces does "
                  "not converge in the peak force (levels 3-5 of the default "
                  "scene change it by -0.82 %, then +0.82 %); use Degree = 1 "
                  "(doc/contact.md)."));
  }



  void
  check_incompatible_modes(const Parameters &p)
  {
    // The modes are condensed out of the elastic stiffness of a Q1 brick;
    // the plastic return, the thermal load and the pre-stress paths take
    // the brick's strain without them, so those are refused rather than
    // written with a strain the stiffness does not have.
    if (!p.finite_element.incompatible_modes)
      return;
    const std::string name = "Finite element/Incompatible modes = true";
    AssertThrow(p.finite_element.degree == 1,
                ExcMessage(name + " is for the 8-node brick: set Degree = 1 "
                                  "(Degree = 2 does not lock in bending)."));
    AssertThrow(!p.finite_element.mean_dilatation,
                ExcMessage(name + " with Volumetric strain = cell mean is "
                                  "not offered; use one of the two."));
    AssertThrow(p.strength.plasticity == GradedStrength::Plasticity::none,
                ExcMessage(name + " is for elastic plates: set "
                                  "Material/Plasticity = none, or the modes "
                                  "false."));
    AssertThrow(!p.thermal.active(),
                ExcMessage(name + " with a Thermal/Temperature field is not "
                                  "offered (its thermal strain has no share "
                                  "in the modes); set the modes false."));
    // Under the point force, the converged mode's in-plane chain (the
    // thickness layers kept) makes the bricks under the load tall and
    // narrow, and without their parasitic shear they punch in: the
    // mid-plane deflection of the 10 x 6 x 2 hertz midplane scene changed
    // by 3.5, 3.8, then 26 % per halving (doc/validation.md).
    AssertThrow(!(p.accuracy.preset == AccuracyPreset::Preset::converged &&
                  p.contact_model.model ==
                    ContactModelParameters::Model::hertz_midplane),
                ExcMessage(name + " with Accuracy = converged and "
                                  "Contact/Model = hertz midplane: under its "
                                  "point force the in-plane refinement does "
                                  "not converge (the mid-plane deflection "
                                  "changed by 3.5, 3.8, 26 % per halving); "
                                  "use resolved sphere, or the modes "
                                  "false."));
  }



  void
  check_named_materials(const Parameters &p)
  {
    // Touloukian's laws are cubic fits: SUS304's E turns negative near
    // 1490 K. Every temperature of the field lies between the faces' (the
    // conduction profile is monotone), sampled every kelvin.
    const double T0 = std::min(p.thermal.face_temperature(true),
                               p.thermal.face_temperature(false)),
                 T1 = std::max(p.thermal.face_temperature(true),
                               p.thermal.face_temperature(false));
    const std::pair<const char *, NamedMaterial> phases[] = {
      {"Metal material", p.material.metal_material},
      {"Ceramic material", p.material.ceramic_material}};
    for (const auto &[entry, named] : phases)
      if (named != NamedMaterial::constant)
        for (double T = T0; T <= T1 + 0.5; T += 1.)
          {
            const ConstituentState s =
              constituent_state(named, std::min(T, T1));
            const bool ok = s.E > 0. && s.nu > -1. && s.nu < 0.5 && s.k > 0.;
            AssertThrow(ok,
                        ExcMessage(
                          std::string("Material/") + entry + " = " +
                          (entry[0] == 'M' ? metal_material_names() :
                                             ceramic_material_names())
                            .name(named) +
                          ": its temperature law gives " +
                          (s.E <= 0. ? "a Young's modulus <= 0" :
                           s.k <= 0. ? "a conductivity <= 0" :
                                       "a Poisson's ratio outside (-1, 0.5)") +
                          " at " +
                          std::to_string(static_cast<int>(std::min(T, T1))) +
                          " K, outside its fit; lower the Thermal "
                          "temperatures."));
          }
  }
} // namespace fgimpact
