#!/usr/bin/env bash
# Configure (Release), build with 2 jobs and run the whole test suite.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j2 --target fgimpact
# mpirun refuses to start as root unless told (CI runs as root), and the
# 2-rank tests may share the machine's cores with other tests.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
# Local ranks only: Open MPI 4 refuses to start without ssh/rsh on PATH
# (a fresh Debian has neither) unless the remote agent is unset.
export OMPI_MCA_plm_rsh_agent=
# deal.II's test macros build each test when ctest runs it.
(cd build && ctest -j2 --output-on-failure)
