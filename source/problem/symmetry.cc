#include <deal.II/base/exceptions.h>

#include <fgimpact/problem/symmetry.h>

#include <cmath>

namespace fgimpact
{
  namespace
  {
    /// Why the plane x = a/2 (d = 0) or y = b/2 (d = 1) is no symmetry
    /// plane of the scene; "" if it is one.
    std::string
    symmetry_breaker(const Parameters &parameters, const unsigned int d)
    {
      const auto       &g    = parameters.geometry;
      const char        axis = (d == 0 ? 'x' : 'y');
      const std::string plane =
        (d == 0 ? std::string("x = a/2") : std::string("y = b/2"));
      if (parameters.problem_type == ProblemType::modal)
        return "Problem type = modal (the modes antisymmetric about the cuts "
               "would be missing)";
      // At a given step a part's explicit history equals the whole
      // plate's; the automatic step is 2/omega_max of the part, whose
      // spectrum holds the symmetric modes only (the default scene: 1.3e-4
      // longer than the whole plate's step).
      if (parameters.time_integration.scheme ==
            TimeStepper::Scheme::central_difference &&
          parameters.time_integration.time_step == 0.)
        return "Time integration/Scheme = explicit with Time step = 0 (a "
               "part's automatic stable step sees only its symmetric modes; "
               "give the Time step to model a part)";
      const double at =
        (d == 0 ? parameters.impactor.impact_x : parameters.impactor.impact_y);
      const double extent = (d == 0 ? g.length : g.width);
      if (at >= 0 && std::abs(at - 0.5 * extent) > 1e-9 * extent)
        return std::string("Impactor/Impact point ") + axis + " = " +
               std::to_string(at) + " m is off the plane " + plane;
      if (g.supports[2 * d] != g.supports[2 * d + 1])
        return "Boundary conditions/" + PlateGeometry::side_names[2 * d] +
               " and " + PlateGeometry::side_names[2 * d + 1] + " differ";
      // probes.csv samples the modelled part only (x <= a/2, y <= b/2).
      for (const auto &p : parameters.output.probe_points.points)
        if (p.location(g.length, g.width, g.thickness)[d] >
            0.5 * extent * (1. + 1e-9))
          return "Output/Probe points: '" + p.name + "' lies beyond " + plane +
                 " (outside the modelled part)";
      const unsigned int n = (d == 0 ? g.subdivisions_x : g.subdivisions_y);
      if (n % 2 != 0)
        return std::string("Geometry/Subdivisions ") + axis + " = " +
               std::to_string(n) + " is odd (no element faces on " + plane +
               ")";
      return "";
    }
  } // namespace



  SymmetricPart
  resolve_symmetry(const Parameters &parameters)
  {
    const auto   &g = parameters.geometry;
    SymmetricPart part;
    if (g.symmetry == Symmetry::none)
      return part;
    const std::string breaker[2] = {symmetry_breaker(parameters, 0),
                                    symmetry_breaker(parameters, 1)};
    const bool        ok[2]      = {breaker[0].empty(), breaker[1].empty()};
    switch (g.symmetry)
      {
        case Symmetry::quarter:
          for (unsigned int d = 0; d < 2; ++d)
            AssertThrow(ok[d],
                        ExcMessage(
                          "Geometry/Symmetry = quarter: " + breaker[d] + "."));
          part.cut = {{true, true}};
          break;
        case Symmetry::half:
          AssertThrow(
            ok[0] || ok[1],
            ExcMessage("Geometry/Symmetry = half: " + breaker[0] +
                       (breaker[1] == breaker[0] ? "" : ", and " + breaker[1]) +
                       "."));
          part.cut = {{ok[0], !ok[0]}};
          break;
        case Symmetry::automatic:
          part.cut = {{ok[0], ok[1]}};
          if (!ok[0] && !ok[1])
            {
              part.note =
                "symmetry: none (Geometry/Symmetry = auto: " + breaker[0] +
                (breaker[1] == breaker[0] ? "" : "; " + breaker[1]) + ")";
              return part;
            }
          break;
        case Symmetry::none:
          break;
      }
    std::string line =
      "symmetry: " + part_name(part.cut) + " of the plate modelled (";
    if (part.cut[0])
      line += "x <= a/2, u_x = 0 on x = a/2";
    if (part.cut[0] && part.cut[1])
      line += "; ";
    if (part.cut[1])
      line += "y <= b/2, u_y = 0 on y = b/2";
    line += "); forces, masses and energies reported for the whole plate";
    if (g.symmetry == Symmetry::automatic && !(ok[0] && ok[1]))
      line += "; not " + std::string(ok[0] ? "y = b/2" : "x = a/2") + ": " +
              breaker[ok[0] ? 1 : 0];
    part.note = line;
    return part;
  }
} // namespace fgimpact
