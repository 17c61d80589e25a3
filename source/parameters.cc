#include <deal.II/base/exceptions.h>

#include <fgimpact/parameters.h>
#include <fgimpact/study.h>
#include <fgimpact/symmetry.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <string>

namespace fgimpact
{
  namespace
  {
    const char *
    support_name(const SideSupport support)
    {
      return support == SideSupport::simply_supported ? "simply supported" :
             support == SideSupport::clamped          ? "clamped" :
                                                        "free";
    }

    /**
     * The rigid-body motions that the side supports leave free: their
     * number, and the names of the translations and rotations (about axes
     * through the plate's centre) among them.  A rigid motion is affine,
     * so it vanishes on a face if it vanishes at the face's corners: each
     * constrained component at each corner of a supported face is one row
     * of A (6 columns, one per rigid mode), and the free motions are the
     * null space of A, of dimension 6 - rank(A^T A).
     */
    unsigned int
    free_rigid_body_modes(const PlateGeometry::Parameters &g,
                          std::vector<std::string>        &names)
    {
      const double size = std::max({g.length, g.width, g.thickness});
      const std::array<double, 3> extent = {
        {g.length / size, g.width / size, g.thickness / size}};
      double              gram[6][6] = {};
      std::array<bool, 6> moves = {{false, false, false, false, false, false}};
      for (unsigned int face = 0; face < 4; ++face)
        {
          if (g.supports[face] == SideSupport::free)
            continue;
          const unsigned int        normal = face / 2; // 0: x faces, 1: y faces
          std::vector<unsigned int> components = {1 - normal, 2};
          if (g.supports[face] == SideSupport::clamped)
            components = {0, 1, 2};
          for (unsigned int corner = 0; corner < 4; ++corner)
            {
              // The corner, relative to the centre (scaled by the size).
              std::array<double, 3> p;
              p[normal]     = (face % 2 - 0.5) * extent[normal];
              p[1 - normal] = ((corner & 1) - 0.5) * extent[1 - normal];
              p[2]          = ((corner >> 1) - 0.5) * extent[2];
              for (const unsigned int c : components)
                {
                  // Translations e_k, rotations e_r x p, component c.
                  const std::array<std::array<double, 3>, 3> rotation = {
                    {{{0., -p[2], p[1]}},
                     {{p[2], 0., -p[0]}},
                     {{-p[1], p[0], 0.}}}};
                  double row[6];
                  for (unsigned int k = 0; k < 3; ++k)
                    {
                      row[k]     = (c == k) ? 1. : 0.;
                      row[3 + k] = rotation[k][c];
                    }
                  for (unsigned int i = 0; i < 6; ++i)
                    {
                      moves[i] = moves[i] || std::abs(row[i]) > 1e-12;
                      for (unsigned int j = 0; j < 6; ++j)
                        gram[i][j] += row[i] * row[j];
                    }
                }
            }
        }
      // Rank by Gaussian elimination with full (diagonal) pivoting.
      unsigned int rank    = 0;
      bool         used[6] = {};
      for (unsigned int step = 0; step < 6; ++step)
        {
          unsigned int pivot = 6;
          for (unsigned int i = 0; i < 6; ++i)
            if (!used[i] && (pivot == 6 || gram[i][i] > gram[pivot][pivot]))
              pivot = i;
          if (pivot == 6 || gram[pivot][pivot] <= 1e-10)
            break;
          used[pivot] = true;
          ++rank;
          for (unsigned int i = 0; i < 6; ++i)
            if (!used[i])
              {
                const double factor = gram[i][pivot] / gram[pivot][pivot];
                for (unsigned int j = 0; j < 6; ++j)
                  gram[i][j] -= factor * gram[pivot][j];
              }
        }
      const char *mode_names[6] = {"translation in x",
                                   "translation in y",
                                   "translation in z",
                                   "rotation about x",
                                   "rotation about y",
                                   "rotation about z"};
      for (unsigned int k = 0; k < 6; ++k)
        if (!moves[k])
          names.emplace_back(mode_names[k]);
      return 6 - rank;
    }
    /// Refuse K-only problems on a plate with a free rigid-body mode.
    void
    validate_supports(const Parameters &parameters)
    {
      // K alone is singular if a rigid-body motion is free: a static load,
      // and the modal shift-invert with Shift = 0, would solve with it.
      const bool uses_K_alone =
        parameters.problem_type == ProblemType::static_load ||
        (parameters.problem_type == ProblemType::modal &&
         parameters.modal.shift == 0.);
      if (!uses_K_alone)
        return;
      std::vector<std::string> names;
      const unsigned int       n_free =
        free_rigid_body_modes(parameters.geometry, names);
      if (n_free == 0)
        return;
      std::ostringstream text;
      text << "Boundary conditions: the supports (";
      for (unsigned int face = 0; face < 4; ++face)
        text << (face ? ", " : "") << PlateGeometry::side_names[face] << " = "
             << support_name(parameters.geometry.supports[face]);
      text << ") leave " << n_free << " rigid-body mode"
           << (n_free > 1 ? "s" : "") << " free (";
      for (unsigned int i = 0; i < names.size(); ++i)
        text << (i ? ", " : "") << names[i];
      text << (names.empty() ? "" : ", ") << "of 6)";
      text << ", so the stiffness matrix of the "
           << (parameters.problem_type == ProblemType::static_load ?
                 "static problem" :
                 "modal problem with Modal/Shift = 0")
           << " is singular; support more faces (Boundary conditions/Face x "
              "min ... Face y max)"
           << (parameters.problem_type == ProblemType::modal ?
                 " or set Modal/Shift > 0" :
                 "")
           << ".";
      AssertThrow(false, ExcMessage(text.str()));
    }
  } // namespace

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
    StudyParameters::declare_parameters(prm);
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
    geometry.symmetry_note = resolve_symmetry(*this);
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
    // Unconditional stability of Newmark: 2 beta >= gamma >= 1/2.
    AssertThrow(
      explicit_scheme || (2. * ti.newmark.beta >= ti.newmark.gamma - 1e-14 &&
                          ti.newmark.gamma >= 0.5 - 1e-14),
      ExcMessage(
        "Time integration/Newmark beta = " + std::to_string(ti.newmark.beta) +
        " with Newmark gamma = " + std::to_string(ti.newmark.gamma) +
        " is not unconditionally stable: that needs 2 "
        "beta >= gamma >= 1/2 (beta = 1/4, gamma = 1/2 is "
        "the default)."));
    AssertThrow(!(explicit_scheme &&
                  contact_model.model ==
                    ContactModelParameters::Model::resolved_sphere),
                ExcMessage("Contact/Model = resolved sphere needs Time "
                           "integration/Scheme = implicit: its contact is "
                           "rigid, which no explicit step is stable for."));
    AssertThrow(output.directory.find_first_not_of(" \t") != std::string::npos,
                ExcMessage("Output/Directory is empty."));
    AssertThrow(2. * impactor.radius <= std::min(a, b),
                ExcMessage(
                  "Impactor/Radius = " + std::to_string(impactor.radius) +
                  " m: the ball is wider than the plate (diameter "
                  "above min(Length a, Width b) = " +
                  std::to_string(std::min(a, b)) + " m)."));
    validate_supports(*this);
    output.probe_points.validate(a, b, geometry.thickness);
  }

  std::vector<std::string>
  Parameters::warnings() const
  {
    std::vector<std::string> result;
    const bool               at_a_point =
      problem_type == ProblemType::impact ||
      (problem_type == ProblemType::static_load &&
       static_analysis.load == StaticAnalysis::Load::point);
    if (!at_a_point)
      return result;
    const double   a = geometry.length, b = geometry.width;
    const Point<2> p      = Impactor(impactor).impact_point(a, b);
    const double   dx     = a / geometry.subdivisions_x;
    const double   dy     = b / geometry.subdivisions_y;
    const double   offset = std::hypot(p[0] - std::round(p[0] / dx) * dx,
                                     p[1] - std::round(p[1] / dy) * dy);
    if (offset <= 1e-6 * std::min(dx, dy))
      return result;
    std::ostringstream text;
    text << "no node lies under Impactor/Impact point (" << p[0] << ", " << p[1]
         << ") m: the force acts at the nearest top node, " << offset * 1e3
         << " mm away";
    const bool central =
      std::abs(p[0] - a / 2) < 1e-9 * a && std::abs(p[1] - b / 2) < 1e-9 * b;
    if (central && (geometry.subdivisions_x % 2 || geometry.subdivisions_y % 2))
      text << " (odd Geometry/Subdivisions x = " << geometry.subdivisions_x
           << ", y = " << geometry.subdivisions_y
           << " put no node at the centre)";
    text << "; choose Geometry/Subdivisions so that a node lies there.";
    result.push_back(text.str());
    return result;
  }
} // namespace fgimpact
