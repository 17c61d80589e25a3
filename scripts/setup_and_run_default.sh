#!/usr/bin/env bash
# Install the dependencies (Debian 12, as root), build fgimpact in Release and
# run the default scene prm/default.prm; results land in output/default/,
# its pictures in output/default/pictures/ (scripts/render.sh), all of it on
# one page, output/default/report.html.
set -euo pipefail
cd "$(dirname "$0")/.."
export DEBIAN_FRONTEND=noninteractive
apt-get update
apt-get install -y --no-install-recommends \
  libdeal.ii-dev numdiff cmake make g++ perl openmpi-bin \
  libsuitesparse-dev libeigen3-dev libopenblas0-serial python3-matplotlib \
  paraview python3-paraview xvfb xauth
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j2 --target fgimpact
./build/fgimpact prm/default.prm
# The standard pictures (output/default/pictures/, ParaView headless).
scripts/render.sh output/default
# The run's report.html again, now with the pictures.
python3 scripts/report.py output/default
