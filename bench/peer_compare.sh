#!/usr/bin/env bash
# Side by side with the independent FEniCSx script (issue 11.6): the
# script's reference scene (homogeneous aluminium, 40 x 20 x 4 trilinear
# bricks, dt = 1 us, 300 steps, V0 = 1 m/s, K_h = 9.421114e9 N/m^1.5, ball
# 0.110 kg; see ../shared/peers/README.md) in the FEniCSx script and in
# fgimpact, alternating, N times each (default 5), whole process wall time.
# Prints the medians, their ratios and the peak forces.
#
#   bench/peer_compare.sh [--runs N] [--out DIR] [--scheme implicit|explicit]
#                         [--symmetry "auto none"] [--time-step DT]
#
# --time-step: the explicit scheme's Time step in s (default 0: automatic).
# Symmetry = auto models the whole plate for the automatic explicit step (a
# part's stable step sees only its symmetric modes) and the quarter at a
# given step, with the whole plate's history to round-off.
#
# --symmetry: the Geometry/Symmetry values to time in fgimpact, each in
# every round (default "auto none": the quarter model the central impact
# allows, and the whole plate); the first is the one the ratio is quoted
# for.
#
# Environment: FGIMPACT (default build/fgimpact; copied to DIR first),
# PEER (default /work/shared/peers/fenicsx/plate_fenicsx.py, or
# ../shared/peers/fenicsx/plate_fenicsx.py from the repository root).
# The script needs Debian's python3-dolfinx under /usr/bin/python3.
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/fgimpact_lib.sh

runs=5 out=output/peer_compare scheme=implicit symmetries="auto none" step=0
while [ $# -gt 0 ]; do
  case $1 in
    --runs) runs=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --scheme) scheme=$2; shift 2 ;;
    --symmetry) symmetries=$2; shift 2 ;;
    --time-step) step=$2; shift 2 ;;
    -h|--help) sed -n '2,25p' "$0"; exit 0 ;;
    *) echo "unknown option $1 (see --help)" >&2; exit 1 ;;
  esac
done

peer=${PEER:-}
for p in "$peer" ../shared/peers/fenicsx/plate_fenicsx.py \
         /work/shared/peers/fenicsx/plate_fenicsx.py; do
  [ -n "$p" ] && [ -f "$p" ] && { peer=$p; break; }
done
[ -f "$peer" ] || { echo "peer_compare: the FEniCSx script is not found (set PEER)" >&2; exit 1; }
/usr/bin/python3 -c 'import dolfinx' 2> /dev/null || {
  echo "peer_compare: /usr/bin/python3 cannot import dolfinx" \
       "(apt-get install -y --no-install-recommends python3-dolfinx)" >&2; exit 1; }

mkdir -p "$out"
out=$(cd "$out" && pwd)
exe=$(copy_executable "$out")
peer=$(cd "$(dirname "$peer")" && pwd)/$(basename "$peer")

# The same scene in fgimpact: prm/default.prm with the script's material,
# contact stiffness, ball mass and end time; no VTU (the script writes none).
fg_args=(prm/default.prm
  -s "Material/Power-law index=0" -s "Contact/Contact stiffness=9.421114e9"
  -s "Impactor/Mass=0.110" -s "Time integration/End time=300e-6"
  -s "Output/VTU interval=0" -s "Output/Log interval=0")
if [ "$scheme" = explicit ]; then
  fg_args+=(-s "Time integration/Scheme=explicit" -s "Time integration/Time step=$step")
fi

now() { date +%s.%N; }
median() { sort -g | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }

# The script writes its history CSV into its working directory: run it in
# DIR.  One untimed run each: the script compiles its forms on the first run.
run_fg() { # symmetry
  "$exe" "${fg_args[@]}" -s "Geometry/Symmetry=$1" \
    -s "Output/Directory=$out/fgimpact_$1" > "$out/fgimpact_$1.log" 2>&1
}
(cd "$out" && /usr/bin/python3 "$peer" impact 1 --solver mumps) > "$out/peer.log" 2>&1
for sym in $symmetries; do run_fg "$sym"; done

: > "$out/times_peer.txt"
for sym in $symmetries; do : > "$out/times_fgimpact_$sym.txt"; done
for i in $(seq "$runs"); do
  t0=$(now); (cd "$out" && /usr/bin/python3 "$peer" impact 1 --solver mumps) > "$out/peer.log" 2>&1; t1=$(now)
  echo "$t1 - $t0" | bc -l >> "$out/times_peer.txt"
  for sym in $symmetries; do
    t0=$(now); run_fg "$sym"; t1=$(now)
    echo "$t1 - $t0" | bc -l >> "$out/times_fgimpact_$sym.txt"
  done
done

peer_median=$(median < "$out/times_peer.txt")
peer_F=$(sed -n 's/.*Fmax=\([0-9.eE+-]*\) N.*/\1/p' "$out/peer.log")
printf '%-34s %10s %10s %12s %14s\n' "" "median (s)" "ratio" "F sampled" "F interpolated"
printf '%-34s %10.3f %10s %12s %14s\n' "FEniCSx script ($runs runs)" "$peer_median" "1.00" "$peer_F" "-"
for sym in $symmetries; do
  fg_median=$(median < "$out/times_fgimpact_$sym.txt")
  fg_F=$(summary_value "$out/fgimpact_$sym" peak_contact_force_N)
  fg_F_sampled=$(summary_value "$out/fgimpact_$sym" max_sampled_contact_force_N)
  part=$(sed -n 's/^  symmetry: \([a-z]*\) .*/\1/p' "$out/fgimpact_$sym.log")
  printf '%-34s %10.3f %10.2f %12s %14s\n' "fgimpact, Symmetry = $sym (${part:-whole})" \
    "$fg_median" "$(echo "$peer_median / $fg_median" | bc -l)" "$fg_F_sampled" "$fg_F"
  awk -v p="$peer_F" -v f="$fg_F_sampled" -v s="$sym" \
    'BEGIN {printf "  sampled peak force, Symmetry = %s, relative to the script: %.2e\n", s, (f - p) / p}'
done
