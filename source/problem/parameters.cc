#include <deal.II/base/exceptions.h>
#include <deal.II/base/tensor.h>

#include <fgimpact/base/parameter_table.h>
#include <fgimpact/base/selection.h>
#include <fgimpact/problem/parameter_checks.h>
#include <fgimpact/problem/parameters.h>
#include <fgimpact/problem/study_parameters.h>
#include <fgimpact/problem/symmetry.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>

namespace fgimpact
{
  namespace
  {
    /// The names of Problem type.
    const SelectionTable<ProblemType> &
    problem_type_names()
    {
      static const SelectionTable<ProblemType> names = {
        {"impact", ProblemType::impact},
        {"static", ProblemType::static_load},
        {"modal", ProblemType::modal}};
      return names;
    }
  } // namespace



  namespace
  {
    /// A snapshot the run never reaches would be missing without a word:
    /// every Output/Snapshot times entry (s) within the End time (s).
    void
    check_snapshot_times(const std::vector<double> &times,
                         const double               end_time,
                         const std::string         &end_time_name)
    {
      // The files are named for the time in whole ns: two times that round
      // to the same ns would write one file listed twice in the PVD.
      for (unsigned int i = 1; i < times.size(); ++i)
        if (std::llround(times[i] * 1e9) == std::llround(times[i - 1] * 1e9))
          {
            std::ostringstream text;
            text << std::setprecision(10)
                 << "Output/Snapshot times: " << times[i - 1] * 1e6 << " and "
                 << times[i] * 1e6
                 << " us name the same file (the time in whole ns); give "
                    "times at least 1 ns apart.";
            AssertThrow(false, ExcMessage(text.str()));
          }
      for (const double t : times)
        {
          // Until 2026-11 the snapshot times were in µs: such a value, far
          // beyond the end, is named with its likely meaning.
          const bool         in_us = t * 1e-6 <= end_time * (1. + 1e-12);
          std::ostringstream text;
          text << "Output/Snapshot times: " << t << " s is after "
               << "Time integration/" << end_time_name << " (" << end_time
               << " s)";
          if (in_us)
            text << "; the times are in s, as End time (for " << t
                 << " us write " << t * 1e-6 << ")";
          text << ".";
          AssertThrow(t <= end_time * (1. + 1e-12), ExcMessage(text.str()));
        }
    }

    /// The span against the step and the snapshots; with End time = auto,
    /// end_time is the Maximum end time (s).
    void
    check_time_span(const TimeStepper::Parameters &ti,
                    const std::vector<double>     &snapshot_times)
    {
      const std::string end_name =
        ti.auto_end_time ? "Maximum end time" : "End time";
      AssertThrow(ti.end_time >= ti.time_step,
                  ExcMessage("Time integration/" + end_name +
                             " is shorter than one Time step."));
      AssertThrow(ti.time_step == 0 || ti.end_time / ti.time_step < 1e8,
                  ExcMessage("Time integration/" + end_name +
                             " divided by Time step exceeds 1e8 steps."));
      check_snapshot_times(snapshot_times, ti.end_time, end_name);
    }

    const char *
    support_name(const SideSupport support)
    {
      return support == SideSupport::simply_supported ? "simply supported" :
             support == SideSupport::clamped          ? "clamped" :
                                                        "free";
    }

    /**
     * The rows of A for the supports of the four sides and of the bottom
     * face: one per constrained component at each corner of a supported
     * face (a rigid motion t + omega x p is affine, so it vanishes on a
     * face if it vanishes at its corners), one column per mode (t_x, t_y,
     * t_z, omega_x, omega_y, omega_z; p relative to the plate's centre,
     * scaled by the largest dimension).
     */
    std::vector<std::array<double, 6>>
    support_rows(const PlateGeometry::Parameters &g)
    {
      const double size = std::max({g.length, g.width, g.thickness});
      const std::array<double, 3> extent = {
        {g.length / size, g.width / size, g.thickness / size}};
      std::vector<std::array<double, 6>> A;
      // Faces x min, x max, y min, y max (ids 0-3), then z min (id 4).
      for (unsigned int face = 0; face < 5; ++face)
        {
          const SideSupport support =
            face < 4 ? g.supports[face] : g.bottom_support;
          if (support == SideSupport::free)
            continue;
          const unsigned int normal = face / 2; // 0: x, 1: y, 2: z faces
          const unsigned int t1 = (normal + 1) % 3, t2 = (normal + 2) % 3;
          // Simply supported: the side's w and tangential in-plane
          // component (Eq. 2.15), the base's w only.
          // An immovable simply supported side also holds its normal
          // component on the mid-plane (z = 0 here).
          const std::vector<unsigned int> components =
            support == SideSupport::clamped ?
              std::vector<unsigned int>{0, 1, 2} :
            normal == 2 ? std::vector<unsigned int>{2} :
            g.immovable_edges ?
                          std::vector<unsigned int>{1 - normal, 2, normal} :
                          std::vector<unsigned int>{1 - normal, 2};
          for (unsigned int corner = 0; corner < 4; ++corner)
            {
              std::array<double, 3> p;
              p[normal] = (face % 2 - 0.5) * extent[normal];
              p[t1]     = ((corner & 1) - 0.5) * extent[t1];
              p[t2]     = ((corner >> 1) - 0.5) * extent[t2];
              for (const unsigned int c : components)
                {
                  // (t + omega x p)_c: t_c + sum_k omega_k (e_k x p)_c.
                  std::array<double, 6> row = {};
                  row[c]                    = 1.;
                  std::array<double, 3> q   = p;
                  if (c == normal && support != SideSupport::clamped)
                    q[2] = 0.;
                  for (unsigned int k = 0; k < 3; ++k)
                    {
                      const unsigned int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
                      // e_k x p = e_k2 p_k1 - e_k1 p_k2
                      row[3 + k] = (c == k1 ? -q[k2] : c == k2 ? q[k1] : 0.);
                    }
                  A.push_back(row);
                }
            }
        }
      return A;
    }

    /**
     * A basis of the null space of A: reduced row echelon form (partial
     * pivoting, column by column, the translations first), then one
     * vector per free column f with x_f = 1.  Returns (f, x) pairs.
     */
    std::vector<std::pair<unsigned int, std::array<double, 6>>>
    null_space(std::vector<std::array<double, 6>> A)
    {
      std::array<int, 6> pivot_row;
      pivot_row.fill(-1);
      unsigned int rank = 0;
      for (unsigned int col = 0; col < 6 && rank < A.size(); ++col)
        {
          unsigned int best = rank;
          for (unsigned int r = rank; r < A.size(); ++r)
            if (std::abs(A[r][col]) > std::abs(A[best][col]))
              best = r;
          if (std::abs(A[best][col]) <= 1e-10)
            continue;
          std::swap(A[rank], A[best]);
          const double diagonal = A[rank][col];
          for (double &x : A[rank])
            x /= diagonal;
          for (unsigned int r = 0; r < A.size(); ++r)
            if (r != rank && A[r][col] != 0.)
              {
                const double factor = A[r][col];
                for (unsigned int j = 0; j < 6; ++j)
                  A[r][j] -= factor * A[rank][j];
              }
          pivot_row[col] = rank++;
        }
      std::vector<std::pair<unsigned int, std::array<double, 6>>> basis;
      for (unsigned int free = 0; free < 6; ++free)
        if (pivot_row[free] < 0)
          {
            std::array<double, 6> x = {};
            x[free]                 = 1.;
            for (unsigned int col = 0; col < 6; ++col)
              if (pivot_row[col] >= 0)
                x[col] = -A[pivot_row[col]][free];
            basis.emplace_back(free, x);
          }
      return basis;
    }

    /**
     * "translation in x", or "rotation about the z axis through (x, y, z)
     * mm" for the null vector x whose free column is `free`: the axis
     * point nearest the centre, omega x t / |omega|^2, in the plate's
     * coordinates.
     */
    std::string
    describe_rigid_motion(const unsigned int               free,
                          const std::array<double, 6>     &x,
                          const PlateGeometry::Parameters &g)
    {
      const char        *axes = "xyz";
      std::ostringstream name;
      if (free < 3)
        {
          name << "translation in " << axes[free];
          return name.str();
        }
      const double       size = std::max({g.length, g.width, g.thickness});
      const Tensor<1, 3> t({x[0], x[1], x[2]}), w({x[3], x[4], x[5]});
      const Tensor<1, 3> p0  = cross_product_3d(w, t) / (w * w);
      const double centre[3] = {g.length / 2, g.width / 2, g.thickness / 2};
      name << "rotation about ";
      if (std::abs(w[(free + 1) % 3]) + std::abs(w[(free + 2) % 3]) < 1e-10)
        name << "the " << axes[free - 3] << " axis";
      else
        name << "the axis (" << w[0] << ", " << w[1] << ", " << w[2] << ")";
      name << " through (";
      for (unsigned int d = 0; d < 3; ++d)
        name << (d ? ", " : "")
             << std::round((centre[d] + p0[d] * size) * 1e4) / 10.;
      name << ") mm";
      return name.str();
    }

    /// The rigid-body motions that the supports leave free (the null
    /// space of support_rows()), one description each.
    std::vector<std::string>
    free_rigid_body_modes(const PlateGeometry::Parameters &g)
    {
      std::vector<std::string> modes;
      for (const auto &[free, x] : null_space(support_rows(g)))
        modes.push_back(describe_rigid_motion(free, x, g));
      return modes;
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
      const std::vector<std::string> modes =
        free_rigid_body_modes(parameters.geometry);
      if (modes.empty())
        return;
      std::ostringstream text;
      text << "Boundary conditions: the supports (";
      for (unsigned int face = 0; face < 4; ++face)
        text << PlateGeometry::side_names[face] << " = "
             << support_name(parameters.geometry.supports[face]) << ", ";
      text << "Face z min = "
           << support_name(parameters.geometry.bottom_support) << ") leave "
           << modes.size() << " of 6 rigid-body modes free (";
      for (unsigned int i = 0; i < modes.size(); ++i)
        text << (i ? ", " : "") << modes[i];
      text << "), so the stiffness matrix of the "
           << (parameters.problem_type == ProblemType::static_load ?
                 "static problem" :
                 "modal problem with Modal/Shift = 0")
           << " is singular; support more faces (Boundary conditions/Face x "
              "min ... Face z min)"
           << (parameters.problem_type == ProblemType::modal ?
                 " or set Modal/Shift > 0" :
                 "")
           << ".";
      AssertThrow(false, ExcMessage(text.str()));
    }


    /// The time step, the time span, Newmark's stability and the scheme
    /// the contact model needs (bad input throws, naming the entry).
    void
    check_time_integration(const Parameters &p)
    {
      const TimeStepper::Parameters &ti = p.time_integration;
      const bool                     explicit_scheme =
        (ti.scheme == TimeStepper::Scheme::central_difference);
      AssertThrow(ti.time_step > 0 || explicit_scheme,
                  ExcMessage("Time integration/Time step = 0 (automatic) is "
                             "only available with Scheme = explicit."));
      check_time_span(ti, p.output.snapshot_times);
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
                    p.contact_model.model ==
                      ContactModelParameters::Model::resolved_sphere),
                  ExcMessage("Contact/Model = resolved sphere needs Time "
                             "integration/Scheme = implicit: its contact is "
                             "rigid, which no explicit step is stable for."));
    }



    /// Output/Directory not empty; it and Material/Profile file without
    /// '#': parameters.prm must read back as the run was, and '#' starts
    /// a comment there (the directory would change, and its cleaning with
    /// it).
    void
    check_paths(const Parameters &p)
    {
      AssertThrow(p.output.directory.find_first_not_of(" \t") !=
                    std::string::npos,
                  ExcMessage("Output/Directory is empty."));
      for (const auto &[entry, value] :
           {std::pair<std::string, std::string>{"Output/Directory",
                                                p.output.directory},
            {"Material/Profile file", p.material.profile_file}})
        AssertThrow(value.find('#') == std::string::npos,
                    ExcMessage(entry + " '" + value +
                               "' holds '#', which starts a comment in the "
                               "parameters.prm the run writes (reading it "
                               "back would give another path); rename it."));
    }
  } // namespace

  namespace
  {
    /// The entries of Parameters that set a member as they stand.
    const ParameterTable<Parameters> &
    top_level_table()
    {
      using P                              = Parameters;
      static const ParameterTable<P> table = [] {
        ParameterTable<P> t;
        t.add("Problem type",
              &P::problem_type,
              problem_type_names(),
              "impact: the sphere strikes the plate (time history). "
              "static: K u = f under the load of subsection Static. "
              "modal: the lowest natural frequencies and mode "
              "shapes (subsection Modal).");
        return t;
      }();
      return table;
    }
  } // namespace



  void
  Parameters::declare_parameters(ParameterHandler &prm)
  {
    top_level_table().declare(prm);
    AccuracyPreset::Parameters::declare_parameters(prm);
    PlateGeometry::Parameters::declare_parameters(prm);
    StaticAnalysisParameters::declare_parameters(prm);
    ModalAnalysisParameters::declare_parameters(prm);
    FunctionallyGradedMaterial::Parameters::declare_parameters(prm);
    ThermalParameters::declare_parameters(prm);
    GradedStrength::Parameters::declare_parameters(prm);
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
    top_level_table().parse(prm, *this);
    // First, explicitly: a preset rewrites Geometry/Subdivisions and Time
    // integration/Time step in prm (so parameters.prm shows them).
    accuracy.apply(prm);

    geometry.parse_parameters(prm);
    material.parse_parameters(prm);
    thermal.parse_parameters(prm);
    // Named constituents: their faces' values in the constant entries.
    material.use_named_at(thermal.face_temperature(true),
                          thermal.face_temperature(false));
    strength.parse_parameters(prm);
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
    // A half or quarter that the scene does not allow throws here, first
    // (the part itself is decided again where the plate is built).
    resolve_symmetry(*this);
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
    check_time_integration(*this);
    check_plasticity(*this);
    check_resolved_contact_degree(*this);
    check_incompatible_modes(*this);
    check_named_materials(*this);
    check_paths(*this);
    AssertThrow(2. * impactor.radius <= std::min(a, b),
                ExcMessage(
                  "Impactor/Radius = " + std::to_string(impactor.radius) +
                  " m: the ball is wider than the plate (diameter "
                  "above min(Length a, Width b) = " +
                  std::to_string(std::min(a, b)) + " m)."));
    validate_supports(*this);
    output.probe_points.validate(a, b, geometry.thickness);
    check_converged_accuracy(*this);
    check_adaptive_mesh(*this);
  }

  std::vector<std::string>
  Parameters::warnings() const
  {
    std::vector<std::string> result;
    const bool               at_a_point =
      problem_type == ProblemType::impact ||
      (problem_type == ProblemType::static_load &&
       static_analysis.load == StaticAnalysisParameters::Load::point);
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

  bool
  Parameters::uses_resolved_contact() const
  {
    return (problem_type == ProblemType::impact &&
            contact_model.model ==
              ContactModelParameters::Model::resolved_sphere) ||
           (problem_type == ProblemType::static_load &&
            static_analysis.load == StaticAnalysisParameters::Load::sphere);
  }
} // namespace fgimpact
