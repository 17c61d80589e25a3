#!/usr/bin/env bash
# The interaction of the error sources (issue 38): the scene of
# tests/unit/converged_accuracy.cc (hertz midplane, 10x6x2 input, quarter
# plate, dt 0.25 us) refined in every direction at once from its 4 % run's
# final mesh: 20x12x4 at level 2, 40x24x8/3, 80x48x16/4, 160x96x32/5.  Each
# quantity's change per step, its observed order and the limit it
# extrapolates to, read from history.csv (max force, max mid-plane
# deflection, max approach; the ball's velocity where the force first
# returns to zero).  The last run has 596k DoFs and needed 10.4 GB and
# 36 min (End time = auto runs on to 357 us; the numbers are fixed by
# 114 us).  Usage: bench/converged_diagonal.sh [DIR]  (default: a temporary
# directory); FGIMPACT=path/to/fgimpact to use another executable.
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/fgimpact_lib.sh
root=${1:-$(mktemp -d)}
mkdir -p "$root"
exe=$(copy_executable "$root")
need_gnu_time
runs=("A 20 12 4 2" "B 40 24 8 3" "C 80 48 16 4" "D 160 96 32 5")
for spec in "${runs[@]}"; do
  set -- $spec
  [ -f "$root/out_$1/summary.txt" ] && continue
  cat >"$root/$1.prm" <<PRM
subsection Geometry
 set Subdivisions x = $2
 set Subdivisions y = $3
 set Subdivisions z = $4
 set Symmetry = auto
 set Contact refinement levels = $5
end
subsection Contact
 set Model = hertz midplane
end
subsection Time integration
 set Time step = 0.25e-6
end
subsection Output
 set Directory = $root/out_$1
 set VTU interval = 0
 set Log interval = 0
 set Print timing = false
 set Probe points = top: 0.5a, 0.5b, 1h
end
PRM
  /usr/bin/time -v "$exe" "$root/$1.prm" >"$root/$1.log" 2>"$root/$1.time"
  echo "$1: $2x$3x$4 level $5: $(gnu_time_elapsed_s "$root/$1.time") s, $(gnu_time_rss_mb "$root/$1.time") MB"
done
for spec in "${runs[@]}"; do
  set -- $spec
  awk -F, -v r="$1" 'NR > 1 {
      if ($2 > F) F = $2; if ($7 > W) W = $7; if ($4 > A) A = $4
      if ($2 > 0) on = 1
      if (on && !off && $2 <= 0) { off = 1; V = -$6 } }
    END { printf "%s %.4f %.7f %.5f %.5f\n", r, F, V, W, A }' \
    "$root/out_$1/history.csv"
done | awk '
  { name[NR] = $1; for (k = 2; k <= 5; ++k) q[NR, k] = $k }
  END {
    split("peak_force_N departure_velocity_m_s midplane_deflection_um approach_um", label)
    for (k = 2; k <= 5; ++k) {
      printf "%-24s", label[k - 1]
      for (i = 1; i <= NR; ++i) printf " %12.7g", q[i, k]
      printf "\n%-24s", "  change %"
      for (i = 2; i <= NR; ++i) printf " %12.3f", 100 * (q[i, k] / q[i - 1, k] - 1)
      d1 = q[NR - 1, k] - q[NR - 2, k]; d2 = q[NR, k] - q[NR - 1, k]
      if (d1 * d2 <= 0 || d1 * d1 <= d2 * d2) {
        printf "\n%-24s no order: the last two changes do not shrink with one sign\n", ""
        continue
      }
      p = log(d1 / d2) / log(2)
      limit = q[NR, k] + d2 / (2 ^ p - 1)
      printf "\n%-24s order %.2f (last two changes), limit %.7g\n", "", p, limit
    }
  }'
