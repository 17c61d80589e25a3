#!/usr/bin/env bash
# Side by side with the independent FEniCSx script (issue 11.6): the
# script's reference scene (homogeneous aluminium, 40 x 20 x 4 trilinear
# bricks, dt = 1 us, 300 steps, V0 = 1 m/s, K_h = 9.421114e9 N/m^1.5, ball
# 0.110 kg; see ../shared/peers/README.md) in the FEniCSx script and in
# fgimpact, alternating, N times each (default 5), whole process wall time.
# Prints both medians, their ratio and both peak forces.
#
#   bench/peer_compare.sh [--runs N] [--out DIR] [--scheme implicit|explicit]
#
# Environment: FGIMPACT (default build/fgimpact; copied to DIR first),
# PEER (default /work/shared/peers/fenicsx/plate_fenicsx.py, or
# ../shared/peers/fenicsx/plate_fenicsx.py from the repository root).
# The script needs Debian's python3-dolfinx under /usr/bin/python3.
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/fgimpact_lib.sh

runs=5 out=output/peer_compare scheme=implicit
while [ $# -gt 0 ]; do
  case $1 in
    --runs) runs=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --scheme) scheme=$2; shift 2 ;;
    -h|--help) sed -n '2,14p' "$0"; exit 0 ;;
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
  -s "Output/VTU interval=0" -s "Output/Log interval=0"
  -s "Output/Directory=$out/fgimpact")
if [ "$scheme" = explicit ]; then
  fg_args+=(-s "Time integration/Scheme=explicit" -s "Time integration/Time step=0")
fi

now() { date +%s.%N; }
median() { sort -g | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }

# The script writes its history CSV into its working directory: run it in
# DIR.  One untimed run each: the script compiles its forms on the first run.
(cd "$out" && /usr/bin/python3 "$peer" impact 1 --solver mumps) > "$out/peer.log" 2>&1
"$exe" "${fg_args[@]}" > "$out/fgimpact.log" 2>&1

: > "$out/times_peer.txt"; : > "$out/times_fgimpact.txt"
for i in $(seq "$runs"); do
  t0=$(now); (cd "$out" && /usr/bin/python3 "$peer" impact 1 --solver mumps) > "$out/peer.log" 2>&1; t1=$(now)
  echo "$t1 - $t0" | bc -l >> "$out/times_peer.txt"
  t0=$(now); "$exe" "${fg_args[@]}" > "$out/fgimpact.log" 2>&1; t1=$(now)
  echo "$t1 - $t0" | bc -l >> "$out/times_fgimpact.txt"
done

peer_median=$(median < "$out/times_peer.txt")
fg_median=$(median < "$out/times_fgimpact.txt")
peer_F=$(sed -n 's/.*Fmax=\([0-9.eE+-]*\) N.*/\1/p' "$out/peer.log")
fg_F=$(summary_value "$out/fgimpact" peak_contact_force_N)
fg_F_sampled=$(summary_value "$out/fgimpact" max_sampled_contact_force_N)
printf '%-28s %10s %10s\n' "" "FEniCSx" "fgimpact"
printf '%-28s %10.3f %10.3f\n' "median wall time (s), $runs runs" "$peer_median" "$fg_median"
printf '%-28s %10s %10s\n' "peak force (N), sampled" "$peer_F" "$fg_F_sampled"
printf '%-28s %10s %10s\n' "peak force (N), interpolated" "-" "$fg_F"
awk -v p="$peer_median" -v f="$fg_median" 'BEGIN {printf "ratio FEniCSx / fgimpact: %.2f\n", p / f}'
awk -v p="$peer_F" -v f="$fg_F_sampled" 'BEGIN {printf "sampled peak force, relative difference: %.2e\n", (f - p) / p}'
