// Checkpoint payloads by named, versioned sections: each component's
// section is found by name whatever the order of writing, its values come
// back bit for bit, and a missing section or another version is refused
// with one message naming the section.

#include <deal.II/base/mpi.h>

#include <fgimpact/base/checkpoint.h>
#include <fgimpact/base/exceptions.h>

#include <cstdio>
#include <limits>
#include <string>

namespace fgimpact_unit_tests::checkpoint_sections
{

  using namespace fgimpact;

  namespace
  {
    /// The message of the ExcMessage that f throws ("" if none).
    template <typename F>
    std::string
    error_of(const F &f)
    {
      try
        {
          f();
        }
      catch (const ExcMessage &e)
        {
          return message_of(e);
        }
      return "";
    }
  } // namespace

  int
  test_main(int argc, char **argv)
  {
    Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

    const double x = 1. / 3., y = std::numeric_limits<double>::min();
    const std::vector<double> values = {2.5, -0.1, 1e300};
    CheckpointWriter          out;
    out.section("first", 1, [&](CheckpointWriter &s) { s.put(x); });
    out.section("second", 7, [&](CheckpointWriter &s) {
      s.put(values);
      s.put(std::string("text"));
    });
    out.section("third", 2, [&](CheckpointWriter &s) { s.put(y); });

    CheckpointReader in(out.data());
    in.step = 42;
    // Read in the opposite order.
    double              x_back = 0, y_back = 0;
    std::vector<double> values_back;
    std::string         text_back;
    CheckpointReader    third = in.section("third", 2);
    third.get(y_back);
    CheckpointReader second = in.section("second", 7);
    second.get(values_back);
    second.get(text_back);
    CheckpointReader first = in.section("first", 1);
    first.get(x_back);
    const bool same = x_back == x && y_back == y && values_back == values &&
                      text_back == "text" && first.step == 42;
    std::printf("three sections read back in reverse order: bit-identical %s, "
                "step carried %s\n",
                same ? "yes" : "no",
                first.step == 42 ? "yes" : "no");

    const std::string missing = error_of([&]() { in.section("fourth", 1); });
    const std::string version = error_of([&]() { in.section("second", 8); });
    const std::string beyond  = error_of([&]() {
      double           z;
      CheckpointReader s = in.section("first", 1);
      s.get(z);
      s.get(z); // past the section's end
    });
    std::printf("missing section: %s\n", missing.c_str());
    std::printf("other version: %s\n", version.c_str());
    std::printf("reading past a section: %s\n", beyond.c_str());
    const bool ok =
      same && missing.find("no section 'fourth'") != std::string::npos &&
      version.find("'second' has version 7") != std::string::npos &&
      version.find("reads version 8") != std::string::npos &&
      beyond.find("ends early") != std::string::npos;
    std::printf(ok ? "all checks passed\n" : "CHECK FAILED\n");
    return ok ? 0 : 1;
  }
} // namespace fgimpact_unit_tests::checkpoint_sections
