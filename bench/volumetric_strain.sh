#!/bin/bash
# The B-bar brick's cost against the paper's: the default scene with the
# resolved sphere (elastic, 40 x 20 x 4, 5 contact levels, 400 us, no VTU),
# Finite element/Volumetric strain = cell mean (A) against pointwise (B),
# whole processes, paired (farm-bench). Usage: bench/volumetric_strain.sh
# [BUILD_DIR] [RUNS]; Release build.
set -euo pipefail
build=${1:-build}
runs=${2:-5}
root=$(cd "$(dirname "$0")/.." && pwd)
exe=$(cd "$build" && pwd)/fgimpact
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
common=(-s "Contact/Model=resolved sphere" -s "Output/VTU interval=0")
run() { # name, volumetric strain
  echo "$exe $root/prm/default.prm ${common[*]@Q} -s 'Finite element/Volumetric strain=$2' -s 'Output/Directory=$out/$1'"
}
farm-bench -n "$runs" --timeout 600 \
  --vs "sh -c \"exec $(run pointwise pointwise) >/dev/null 2>&1\"" \
  -- sh -c "exec $(run bbar 'cell mean') >/dev/null 2>&1"
