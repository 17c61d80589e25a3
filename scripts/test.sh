#!/usr/bin/env bash
# Configure (Release), build with 2 jobs and run the whole test suite.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j2 --target fgimpact
# deal.II's test macros build each test when ctest runs it.
(cd build && ctest -j2 --output-on-failure)
