#!/usr/bin/env bash
# The cost of the VTU output of the default scene (issues 25 and 41): the
# whole run (start-up included) of prm/default.prm as it is now (the whole
# plate from the quarter, zlib `speed`, the peak snapshot, End time = auto)
# against the same with raw binary VTU (the default until 2026-11), the
# quarter's VTU only (zlib `speed`, no peak snapshot), and no VTU at all;
# N runs of each, interleaved, with GNU time: the median wall time, the
# median peak RSS and the size of the output directory.
# Usage: bench/vtu_output.sh [N]   (default 7; about 30 s)
#        FGIMPACT=path/to/fgimpact to use another executable.
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/fgimpact_lib.sh
exe=${FGIMPACT:-build/fgimpact}
need_gnu_time
n=${1:-7}
root=$(mktemp -d)
trap 'rm -rf "$root"' EXIT
labels=(whole-speed quarter-speed whole-raw no-vtu)
options=(
  ""
  "-s Output/Mirror?symmetric?part=false -s Output/Snapshot?at?peak?force=false"
  "-s Output/VTU?compression=none"
  "-s Output/VTU?interval=0 -s Output/Snapshot?at?peak?force=false"
)
for ((run = 0; run < n; ++run)); do
  for k in "${!labels[@]}"; do
    dir="$root/${labels[$k]}"
    timed_default_run "$exe" "$dir" "$root/time" "${options[$k]}"
    echo "$(tail -n 1 "$root/time") $(du -sk "$dir" | cut -f1)" >>"$root/${labels[$k]}.txt"
  done
done
echo "| output | whole run (s, median of $n) | peak RSS (MB) | directory (MB) |"
echo "|---|---|---|---|"
for label in "${labels[@]}"; do
  wall=$(cut -d' ' -f1 "$root/$label.txt" | median)
  rss=$(cut -d' ' -f2 "$root/$label.txt" | median)
  size=$(cut -d' ' -f3 "$root/$label.txt" | median)
  awk -v l="$label" -v w="$wall" -v r="$rss" -v s="$size" \
    'BEGIN {printf "| %s | %.2f | %.0f | %.1f |\n", l, w, r / 1024, s / 1024}'
done
