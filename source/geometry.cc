#include <deal.II/grid/grid_generator.h>

#include <fgimpact/geometry.h>

namespace fgimpact
{
  const std::array<std::string, 4> PlateGeometry::side_names = {
    {"Face x min", "Face x max", "Face y min", "Face y max"}};



  void
  PlateGeometry::Parameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Geometry");
    {
      prm.declare_entry("Length a",
                        "0.2",
                        Patterns::Double(1e-6, 1e3),
                        "Plate length a along x. Unit: m.");
      prm.declare_entry("Width b",
                        "0.1",
                        Patterns::Double(1e-6, 1e3),
                        "Plate width b along y. Unit: m.");
      prm.declare_entry("Thickness h",
                        "0.02",
                        Patterns::Double(1e-6, 1e3),
                        "Plate thickness h along z; z = 0 is the (ceramic) "
                        "bottom face, z = h the (metal) top face that the "
                        "impactor strikes. Unit: m.");
      prm.declare_entry("Subdivisions x",
                        "40",
                        Patterns::Integer(1, 100000),
                        "Number of elements along x. Even, so that a node "
                        "lies under a central impact.");
      prm.declare_entry("Subdivisions y",
                        "20",
                        Patterns::Integer(1, 100000),
                        "Number of elements along y.");
      prm.declare_entry("Subdivisions z",
                        "4",
                        Patterns::Integer(1, 100000),
                        "Number of elements through the thickness.");
    }
    prm.leave_subsection();

    prm.enter_subsection("Boundary conditions");
    {
      for (const auto &name : side_names)
        prm.declare_entry(
          name,
          "simply supported",
          Patterns::Selection("simply supported|clamped|free"),
          "Support of this whole side face (x min: x = 0, x max: x = a, y "
          "min: y = 0, y max: y = b). simply supported (Eq. 2.15): "
          "w = 0 and the tangential in-plane displacement = 0 on the face "
          "(v on x = const, u on y = const); the normal in-plane "
          "displacement is free. clamped: u = v = w = 0. free: traction "
          "free.");
    }
    prm.leave_subsection();
  }



  void
  PlateGeometry::Parameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Geometry");
    {
      length         = prm.get_double("Length a");
      width          = prm.get_double("Width b");
      thickness      = prm.get_double("Thickness h");
      subdivisions_x = prm.get_integer("Subdivisions x");
      subdivisions_y = prm.get_integer("Subdivisions y");
      subdivisions_z = prm.get_integer("Subdivisions z");
    }
    prm.leave_subsection();

    prm.enter_subsection("Boundary conditions");
    {
      for (unsigned int f = 0; f < 4; ++f)
        {
          const std::string s = prm.get(side_names[f]);
          supports[f] =
            (s == "simply supported" ? SideSupport::simply_supported :
             s == "clamped"          ? SideSupport::clamped :
                                       SideSupport::free);
        }
    }
    prm.leave_subsection();
  }



  PlateGeometry::PlateGeometry(const Parameters &parameters)
    : parameters(parameters)
  {}



  void
  PlateGeometry::create_triangulation(Triangulation<3> &triangulation) const
  {
    unsigned int              k = 0;
    std::vector<unsigned int> coarse{parameters.subdivisions_x,
                                     parameters.subdivisions_y,
                                     parameters.subdivisions_z};
    while (coarse[0] % 2 == 0 && coarse[1] % 2 == 0 && coarse[2] % 2 == 0)
      {
        for (auto &n : coarse)
          n /= 2;
        ++k;
      }
    // Boundary ids (colorize) pass to the children of refined faces.
    GridGenerator::subdivided_hyper_rectangle(triangulation,
                                              coarse,
                                              Point<3>(),
                                              Point<3>(parameters.length,
                                                       parameters.width,
                                                       parameters.thickness),
                                              /*colorize=*/true);
    triangulation.refine_global(k);
  }



  Point<3>
  PlateGeometry::centre(const double z) const
  {
    return Point<3>(parameters.length / 2, parameters.width / 2, z);
  }



  bool
  PlateGeometry::contains(const Point<3> &p) const
  {
    const double tol = 1e-12 * parameters.length;
    return p[0] >= -tol && p[0] <= parameters.length + tol && p[1] >= -tol &&
           p[1] <= parameters.width + tol && p[2] >= -tol &&
           p[2] <= parameters.thickness + tol;
  }
} // namespace fgimpact
