#!/usr/bin/env bash
# The paper's eight same-plate cases (Asemi & Salami 2015, sections 4.2:
# V0 = 1, 2, 3, 4 m/s with the default impactor; rho_i = 7800, 8900, 9850,
# 11300 kg/m^3 at V0 = 1 m/s; prm/velocity_v*.prm, prm/density_*.prm) as
# one study invocation against one case (prm/velocity_v1.prm), whole
# process, alternating, REPEATS times each; prints both medians, the ratio
# (target: at most 2) and the peak resident memory of each (/usr/bin/time
# -v).  Then checks that every case's history.csv and summary.txt equal
# the separate runs of prm/<case>.prm in every printed
# digit.
#
# Usage: bench/study_paper_cases.sh [REPEATS]      (default 3)
# Environment: FGIMPACT (default build/fgimpact), OUT (default
# output/bench_study).
set -euo pipefail
repo_root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$repo_root"
. scripts/fgimpact_lib.sh
fgimpact="${FGIMPACT:-build/fgimpact}"
out="${OUT:-output/bench_study}"
repeats="${1:-3}"
mkdir -p "$out"

study_args=(prm/default.prm -s "Output/Directory=$out/study"
  -s "Output/VTU interval=0" -s "Study/Combination=zip"
  --study "Impactor/Initial velocity=1,2,3,4,1,1,1,1"
  --study "Impactor/Density=7800,7800,7800,7800,7800,8900,9850,11300")
one_args=(prm/velocity_v1.prm -s "Output/Directory=$out/one" -s "Output/VTU interval=0")

# Wall time (s) and peak RSS (MB) of one command, from /usr/bin/time -v.
measure() {
  /usr/bin/time -v "$@" > "$out/last.log" 2> "$out/time.txt"
  awk -F': ' '/Elapsed \(wall clock\)/ { n = split($2, p, ":");
                s = p[n] + (n > 1 ? 60 * p[n-1] : 0) + (n > 2 ? 3600 * p[n-2] : 0) }
              /Maximum resident set size/ { m = $2 / 1024 }
              END { printf "%.3f %.1f\n", s, m }' "$out/time.txt"
}

one_times=() study_times=()
for ((r = 0; r < repeats; ++r)); do
  read -r t m1 < <(measure "$fgimpact" "${one_args[@]}")
  one_times+=("$t")
  read -r t m8 < <(measure "$fgimpact" "${study_args[@]}")
  study_times+=("$t")
  cp "$out/last.log" "$out/study.log"
done
median() { printf '%s\n' "$@" | sort -g | awk '{ a[NR] = $1 } END { print a[int((NR + 1) / 2)] }'; }
t1=$(median "${one_times[@]}")
t8=$(median "${study_times[@]}")
printf 'one case (prm/velocity_v1.prm):  median %.2f s of %d, peak RSS %.0f MB\n' "$t1" "$repeats" "$m1"
printf 'eight cases, one study:          median %.2f s of %d, peak RSS %.0f MB\n' "$t8" "$repeats" "$m8"
printf 'ratio eight / one: %.2f (target <= 2)\n' "$(echo "$t8 / $t1" | bc -l)"
grep "study:" "$out/study.log" | sed 's/^ */log: /'

# Equality with separate runs, in every printed digit (summary.txt: apart
# from the provenance, the timings and impulse_identity_error, a round-off
# measure of order 1e-13).
cases=(velocity_v1 velocity_v2 velocity_v3 velocity_v4
       density_7800 density_8900 density_9850 density_11300)
for i in "${!cases[@]}"; do
  c=${cases[$i]}
  "$fgimpact" "prm/$c.prm" -s "Output/Directory=$out/separate/$c" > /dev/null
  d=$(printf '%s/study/case_%03d' "$out" "$i")
  same_history=no; same_summary=no
  cmp -s "$d/history.csv" "$out/separate/$c/history.csv" && same_history=yes
  timing='^(setup_s|factorization_s|time_loop_s|time_per_step_ms|output_s|wall_time_s|impulse_identity_error|#)'
  diff -q <(grep -Ev "$timing" "$d/summary.txt") \
          <(grep -Ev "$timing" "$out/separate/$c/summary.txt") > /dev/null && same_summary=yes
  printf 'case %d = %-14s history.csv identical: %s, summary.txt identical: %s\n' \
    "$i" "$c" "$same_history" "$same_summary"
done
