#!/usr/bin/env bash
# CHOLMOD fill-reducing ordering (Linear solver/CHOLMOD ordering =
# amd|metis|nesdis|auto): factorization time, one solve, time per step and
# peak RSS on the default scene, one run each, per mesh.  Needs a build that
# has the 'CHOLMOD ordering' entry.
#
#   bench/cholmod_ordering.sh [--out DIR] [nx:ny:nz:end_us ...]
set -euo pipefail
cd "$(dirname "$0")/.."

out=output/bench/ordering
if [ "${1:-}" = --out ]; then out=$2; shift 2; fi
cases=("$@")
[ ${#cases[@]} -gt 0 ] || cases=(40:20:4:400 80:40:8:20 120:60:8:10)
[ -x /usr/bin/time ] || { SUDO=""; [ "$(id -u)" -eq 0 ] || SUDO="sudo"; $SUDO apt-get install -y time; }
mkdir -p "$out"
out=$(cd "$out" && pwd)
exe=$out/fgimpact_bench
cp "${FGIMPACT:-build/fgimpact}" "$exe"
"$exe" --print-parameters | grep -q "CHOLMOD ordering" ||
  { echo "this build has no 'CHOLMOD ordering' entry" >&2; exit 1; }

get() { awk -F' = ' -v k="$1" '$1 == k {print $2}' "$2"; }
csv=$out/ordering.csv
echo "mesh,n_dofs,ordering,factorization_s,solve_ms,spmv_ms,time_per_step_ms,peak_rss_MB" > "$csv"
for c in "${cases[@]}"; do
  IFS=: read -r nx ny nz T <<< "$c"
  for ordering in amd metis nesdis auto; do
    dir=$out/${nx}x${ny}x${nz}_$ordering
    mkdir -p "$dir"
    cat > "$dir/run.prm" <<PRM
include prm/default.prm
subsection Geometry
  set Subdivisions x = $nx
  set Subdivisions y = $ny
  set Subdivisions z = $nz
end
subsection Time integration
  set End time = ${T}e-6
end
subsection Linear solver
  set Type = cholmod
  set CHOLMOD ordering = $ordering
end
subsection Output
  set Directory    = $dir
  set VTU interval = 0
  set Log interval = 0
end
PRM
    /usr/bin/time -v -o "$dir/time.txt" "$exe" "$dir/run.prm" > "$dir/log.txt" 2>&1
    s=$dir/summary.txt
    rss=$(awk -F': ' '/Maximum resident set size/ {printf "%.0f", $2 / 1024}' "$dir/time.txt")
    echo "${nx}x${ny}x${nz},$(get n_dofs "$s"),$ordering,$(get factorization_s "$s"),$(get solve_ms "$s"),$(get spmv_ms "$s"),$(get time_per_step_ms "$s"),$rss" | tee -a "$csv"
  done
done
