#!/usr/bin/env bash
# Configure (Release), build with 2 jobs and run the whole test suite.
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/fgimpact_lib.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j2 --target fgimpact
# The 2-rank tests: mpirun as root (CI runs as root), oversubscribed (they
# may share the machine's cores with other tests), without ssh.
allow_local_mpirun
# deal.II's test macros build each test when ctest runs it.
(cd build && ctest -j2 --output-on-failure)
# The plotting script (skips the drawing without matplotlib, as in CI).
scripts/check_plot_histories.sh build

# The unit tests on small meshes again against deal.II's debug library
# (libdeal.ii.g.so), so that its Assert checks (index ranges, dimensions,
# ghost access) run in CI.  Whole-program and slow tests stay Release-only.
debug_tests='^unit/(material_gradation|turner_modulus|newmark_oscillator|parameters_defaults|vtu_stress|plate_mass|patch_test|monolithic_newton)$'
cmake -S . -B build-debug -DCMAKE_BUILD_TYPE=Debug \
  -DTEST_PICKUP_REGEX="$debug_tests"
cmake --build build-debug -j2 --target fgimpact_lib
(cd build-debug && ctest -j2 --output-on-failure)
