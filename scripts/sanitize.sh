#!/usr/bin/env bash
# Build our code (library, executable, tests; not deal.II) against deal.II's
# debug library with AddressSanitizer and UndefinedBehaviorSanitizer, and
# run the small unit tests, the run tests (tests/run/*.prm through the
# executable) and the bad-input suite with it.  Any sanitizer report fails
# (halt_on_error, exit codes 97-99); only Open MPI's own leaks are
# suppressed (tests/lsan.supp).  doc/robustness.md, "Sanitizers".
# Not yet part of scripts/test.sh: see doc/robustness.md for its state.
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/fgimpact_lib.sh
allow_local_mpirun
tests='^(unit/(material_gradation|turner_modulus|newmark_oscillator|parameters_defaults|vtu_stress|plate_mass|patch_test|monolithic_newton|bad_input)|run/.*)$'
cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=Debug -DFGIMPACT_SANITIZE=ON \
  -DTEST_PICKUP_REGEX="$tests"
cmake --build build-sanitize -j2 --target fgimpact
export ASAN_OPTIONS="halt_on_error=1:exitcode=99:detect_leaks=1"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1:exitcode=98"
export LSAN_OPTIONS="suppressions=$PWD/tests/lsan.supp:exitcode=97"
export FGIMPACT_SANITIZED=1
(cd build-sanitize && ctest -j2 --output-on-failure)
