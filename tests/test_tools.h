#ifndef fgimpact_test_tools_h
#define fgimpact_test_tools_h

// Shared by the whole-program tests: run an impact through the library
// exactly as the executable does, on a coarse mesh, with the simulator's
// log kept out of the test output.

#include <deal.II/base/parameter_handler.h>

#include <fgimpact/simulator.h>

#include <filesystem>
#include <iostream>
#include <sstream>
#include <string>

namespace fgimpact_tests
{
  /**
   * Run the impact defined by `settings` (.prm text) on top of the
   * defaults, a 10 x 6 x 2 mesh (later entries in `settings` override it)
   * and a quiet output into ./out.
   */
  inline fgimpact::ImpactResults
  run_impact(const std::string &settings)
  {
    dealii::ParameterHandler prm;
    fgimpact::ImpactSimulator::Parameters::declare_parameters(prm);
    prm.parse_input_from_string(
      "subsection Geometry\n set Subdivisions x = 10\n set Subdivisions y = 6\n"
      " set Subdivisions z = 2\nend\n"
      "subsection Output\n set Directory = out\n set Log interval = 0\n"
      " set Print timing = false\nend\n" +
      settings);
    fgimpact::ImpactSimulator::Parameters p;
    p.parse_parameters(prm);
    p.validate();
    std::filesystem::create_directories(p.output_directory);

    std::ostringstream log;
    auto *const        old = std::cout.rdbuf(log.rdbuf());
    try
      {
        fgimpact::ImpactSimulator simulator(p, MPI_COMM_WORLD);
        simulator.run();
        std::cout.rdbuf(old);
        return simulator.get_results();
      }
    catch (...)
      {
        std::cout.rdbuf(old);
        throw;
      }
  }
} // namespace fgimpact_tests

#endif
