// Accuracy presets (source/problem/accuracy_preset.cc): each preset selects the
// documented discretization (doc/accuracy.md) in the ParameterHandler
// itself, so that parameters.prm shows the effective values:
//  - fast 40x20x2, dt 2 us; standard 40x20x4, dt 1 us; accurate 40x20x16,
//    dt 1 us on the default 0.2 x 0.1 m plate, whatever the file says;
//  - the in-plane element size stays 5 mm on another plate (0.3 x 0.12 m:
//    60 x 24) and the counts are even (a node at the plate centre);
//  - the mesh has 3 (nx+1)(ny+1)(nz+1) DoFs and its contact node lies at
//    the plate centre;
//  - custom changes nothing; a preset with the explicit scheme is refused
//    with a message naming the entries.

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <fgimpact/study/simulator.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <test_tools.h>

namespace fgimpact_unit_tests::accuracy_preset
{

  using namespace fgimpact;

  namespace
  {
    struct Effective
    {
      unsigned int nx, ny, nz;
      double       dt;             // s, from the parsed Parameters
      std::string  prm_nx, prm_dt; // the entries as parameters.prm shows them
      std::string  log;
    };

    Effective
    parse(const std::string &settings)
    {
      ParameterHandler prm;
      fgimpact::Parameters::declare_parameters(prm);
      // A file that asks for another mesh and time step: the preset wins.
      prm.parse_input_from_string(
        "subsection Geometry\n set Subdivisions x = 10\n set Subdivisions y = "
        "6\n set Subdivisions z = 2\nend\nsubsection Time integration\n set "
        "Time step = 5e-6\nend\n" +
        settings);
      fgimpact::Parameters p;
      p.parse_parameters(prm);
      Effective e{p.geometry.subdivisions_x,
                  p.geometry.subdivisions_y,
                  p.geometry.subdivisions_z,
                  p.time_integration.time_step,
                  "",
                  "",
                  p.accuracy.applied_message(p.geometry.subdivisions_x,
                                             p.geometry.subdivisions_y,
                                             p.geometry.subdivisions_z)};
      prm.enter_subsection("Geometry");
      e.prm_nx = prm.get("Subdivisions x");
      prm.leave_subsection();
      prm.enter_subsection("Time integration");
      e.prm_dt = prm.get("Time step");
      prm.leave_subsection();
      return e;
    }

    bool
    report(const std::string &what, const bool ok)
    {
      std::printf("%s: %s\n", what.c_str(), ok ? "yes" : "NO");
      return ok;
    }
  } // namespace

  int
  test_main(int argc, char **argv)
  {
    Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
    bool                             ok = true;

    struct Expected
    {
      const char  *name;
      unsigned int nx, ny, nz;
      double       dt;
    };
    // doc/accuracy.md, "Accuracy presets".
    for (const Expected &x : {Expected{"fast", 40, 20, 2, 2e-6},
                              Expected{"standard", 40, 20, 4, 1e-6},
                              Expected{"accurate", 40, 20, 16, 1e-6}})
      {
        const Effective e = parse(std::string("set Accuracy = ") + x.name);
        std::printf("%s: %u x %u x %u, dt = %g us; %s\n",
                    x.name,
                    e.nx,
                    e.ny,
                    e.nz,
                    e.dt * 1e6,
                    e.log.c_str());
        ok &= report("  documented mesh and time step",
                     e.nx == x.nx && e.ny == x.ny && e.nz == x.nz &&
                       std::abs(e.dt / x.dt - 1) < 1e-12);
        ok &= report("  the ParameterHandler holds the effective values",
                     std::stoul(e.prm_nx) == x.nx &&
                       std::abs(std::stod(e.prm_dt) / x.dt - 1) < 1e-12);
        // The mesh itself: DoF count and the contact node at the centre.
        const auto c = fgimpact_tests::make_plate(e.nx, e.ny, e.nz, 1, 1.);
        const auto node =
          c.plate->nearest_top_vertex_dof(Point<2>(0.1, 0.05), 2).second;
        ok &= report("  3 (nx+1)(ny+1)(nz+1) DoFs",
                     c.plate->n_dofs() ==
                       3u * (e.nx + 1) * (e.ny + 1) * (e.nz + 1));
        ok &= report("  a node at the plate centre",
                     std::abs(node[0] - 0.1) < 1e-12 &&
                       std::abs(node[1] - 0.05) < 1e-12);
      }

    {
      const Effective e =
        parse("set Accuracy = standard\nsubsection Geometry\n"
              " set Length a = 0.3\n set Width b = 0.12\nend\n");
      ok &= report("0.3 x 0.12 m plate, standard: 60 x 24 elements of 5 mm",
                   e.nx == 60 && e.ny == 24 && e.nz == 4);
      const Effective f = parse("set Accuracy = fast\nsubsection Geometry\n"
                                " set Length a = 0.213\nend\n");
      ok &= report("0.213 m, fast: the nearest even count (42, 5.07 mm)",
                   f.nx == 42);
    }
    {
      const Effective e = parse("set Accuracy = custom");
      ok &= report("custom: the file's 10 x 6 x 2 and 5 us",
                   e.nx == 10 && e.ny == 6 && e.nz == 2 &&
                     std::abs(e.dt - 5e-6) < 1e-18 && e.log.empty());
    }
    {
      bool        thrown = false;
      std::string message;
      try
        {
          parse("set Accuracy = fast\nsubsection Time integration\n set "
                "Scheme = explicit\nend\n");
        }
      catch (const ExceptionBase &e)
        {
          thrown  = true;
          message = e.what();
        }
      ok &= report("fast with the explicit scheme: refused, naming Accuracy "
                   "and Scheme",
                   thrown && message.find("Accuracy") != std::string::npos &&
                     message.find("Scheme") != std::string::npos);
    }
    std::printf("%s\n", ok ? "all checks passed" : "SOME CHECKS FAILED");
    return ok ? 0 : 1;
  }
} // namespace fgimpact_unit_tests::accuracy_preset
