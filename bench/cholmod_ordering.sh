#!/usr/bin/env bash
# CHOLMOD fill-reducing ordering (Linear solver/CHOLMOD ordering =
# amd|metis|nesdis|auto): factorization time, one solve, time per step and
# peak RSS on the default scene, one run each, per mesh.  Needs a build that
# has the 'CHOLMOD ordering' entry.
#
#   bench/cholmod_ordering.sh [--out DIR] [nx:ny:nz:end_us ...]
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/fgimpact_lib.sh

out=output/bench/ordering
if [ "${1:-}" = --out ]; then out=$2; shift 2; fi
cases=("$@")
[ ${#cases[@]} -gt 0 ] || cases=(40:20:4:400 80:40:8:20 120:60:8:10)
need_gnu_time
mkdir -p "$out"
out=$(cd "$out" && pwd)
exe=$(copy_executable "$out")
"$exe" --print-parameters | grep -q "CHOLMOD ordering" ||
  { echo "this build has no 'CHOLMOD ordering' entry" >&2; exit 1; }

csv=$out/ordering.csv
echo "mesh,n_dofs,ordering,factorization_s,solve_ms,spmv_ms,time_per_step_ms,peak_rss_MB" > "$csv"
for c in "${cases[@]}"; do
  IFS=: read -r nx ny nz T <<< "$c"
  for ordering in amd metis nesdis auto; do
    dir=$out/${nx}x${ny}x${nz}_$ordering
    mkdir -p "$dir"
    write_prm "$dir/run.prm" prm/default.prm "Geometry/Symmetry=none" \
      "Geometry/Subdivisions x=$nx" "Geometry/Subdivisions y=$ny" \
      "Geometry/Subdivisions z=$nz" "Time integration/End time=${T}e-6" \
      "Linear solver/Type=cholmod" "Linear solver/CHOLMOD ordering=$ordering" \
      "Output/Instrumentation=true" "Output/Directory=$dir" "Output/VTU interval=0" "Output/Log interval=0"
    /usr/bin/time -v -o "$dir/time.txt" "$exe" "$dir/run.prm" > "$dir/run.log" 2>&1
    rss=$(gnu_time_rss_mb "$dir/time.txt")
    vals=$ordering
    for k in factorization_s solve_ms spmv_ms time_per_step_ms; do
      vals+=,$(summary_value "$dir" $k)
    done
    echo "${nx}x${ny}x${nz},$(summary_value "$dir" n_dofs),$vals,$rss" | tee -a "$csv"
  done
done
