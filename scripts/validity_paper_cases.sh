#!/usr/bin/env bash
# The validity report of the paper's 13 cases (prm/*.prm): each with the
# paper's contact (hertz node) and with the resolved sphere, End time = auto,
# no VTU; prints a Markdown table of summary.txt's validity numbers
# (doc/validity.md).
#
# Usage: scripts/validity_paper_cases.sh
# Environment: FGIMPACT (default build/fgimpact), OUT (default
# output/validity_cases).
set -euo pipefail
repo_root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$repo_root"
fgimpact="${FGIMPACT:-build/fgimpact}"
out="${OUT:-output/validity_cases}"
mkdir -p "$out"

key() { awk -F' = ' -v k="$2" '$1 == k { print $2 }' "$1"; }

echo "| case | model | peak force (N) | von Mises / yield | where (x, y, z mm), when (us) | principal / tensile | where, when | rigid ball E* excess |"
echo "|---|---|---|---|---|---|---|---|"
for prm in prm/*.prm; do
  name="$(basename "$prm" .prm)"
  for model in "hertz node" "resolved sphere"; do
    dir="$out/$name/${model// /_}"
    mkdir -p "$out/$name"
    "$fgimpact" "$prm" -s "Contact/Model=$model" -s "Output/Directory=$dir" \
      -s "Output/VTU interval=0" -s "Time integration/End time=auto" \
      -s "Output/Checkpoint interval=0" > "$dir.log" 2>&1 ||
      { echo "| $name | $model | failed: see $dir.log |"; continue; }
    s="$dir/summary.txt"
    printf '| %s | %s | %s | %s | %s, %s, %s; %s | %s | %s, %s, %s; %s | %s |\n' \
      "$name" "$model" "$(key "$s" peak_contact_force_N)" \
      "$(key "$s" max_von_mises_over_yield)" \
      "$(key "$s" von_mises_peak_x_mm)" "$(key "$s" von_mises_peak_y_mm)" \
      "$(key "$s" von_mises_peak_z_mm)" "$(key "$s" von_mises_peak_time_us)" \
      "$(key "$s" max_principal_over_tensile_strength)" \
      "$(key "$s" principal_peak_x_mm)" "$(key "$s" principal_peak_y_mm)" \
      "$(key "$s" principal_peak_z_mm)" "$(key "$s" principal_peak_time_us)" \
      "$(key "$s" rigid_ball_modulus_excess)"
  done
done
