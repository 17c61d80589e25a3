#!/usr/bin/env bash
# Configure (Release), build with 2 jobs and run the whole test suite.
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/fgimpact_lib.sh
# The library's floors: no include runs back up (issue 39; doc/code_map.md, "Code
# map").
scripts/check_floors.py
# No .cc over 500 lines, no function over 60 (pmccabe; doc/code_map.md).
scripts/check_sizes.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
# fgimpact_unit_tests: every unit test's body, built once before ctest
# (its tests would otherwise race to build it; tests/unit/CMakeLists.txt).
cmake --build build -j2 --target fgimpact fgimpact_unit_tests
# The 2-rank tests: mpirun as root (CI runs as root), oversubscribed (they
# may share the machine's cores with other tests), without ssh.
allow_local_mpirun
# deal.II's test macros build each test's launcher when ctest runs it.
(cd build && ctest -j2 --output-on-failure)
# The plotting script (skips the drawing without matplotlib, as in CI).
scripts/check_plot_histories.sh build
# The ParaView pictures (skipped without pvpython; CI installs it).
scripts/check_render.sh build

# The small unit tests, the run tests and the bad-input suite again,
# against deal.II's debug library (its Assert checks) and with
# AddressSanitizer + UndefinedBehaviorSanitizer on our code.
# Whole-program and slow tests stay Release-only.
scripts/sanitize.sh
