// What deal.II's test macro builds for the unit test FGIMPACT_UNIT_TEST
// (a compile definition): it replaces itself (execv: same process, so
// mpirun's ranks stay its ranks) with the one executable that holds every
// unit test, FGIMPACT_UNIT_TESTS, which runs the test's body.  Building
// the bodies once, in unity batches, instead of 61 programs that each
// parse and instantiate deal.II again: tests/unit/CMakeLists.txt.

#include <cstdio>
#include <unistd.h>
#include <vector>

int
main(int argc, char **argv)
{
  std::vector<char *> arguments{const_cast<char *>(FGIMPACT_UNIT_TESTS),
                                const_cast<char *>(FGIMPACT_UNIT_TEST)};
  for (int i = 1; i < argc; ++i)
    arguments.push_back(argv[i]);
  arguments.push_back(nullptr);
  execv(FGIMPACT_UNIT_TESTS, arguments.data());
  std::perror("execv " FGIMPACT_UNIT_TESTS);
  return 1;
}
