#!/usr/bin/env bash
# scripts/contact_convergence.sh for every paper case in prm/, then one
# Markdown table (peak force, contact duration, departure velocity: the
# converged resolved value with its estimated error, and the errors of
# hertz node and hertz midplane in %) in OUT/table.md.
#   scripts/contact_paper_cases.sh [OUT] [TOLERANCE]
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-output/contact_convergence}
tolerance=${2:-0.01}
for prm in prm/*.prm; do
  name=$(basename "$prm" .prm)
  echo "== $name"
  scripts/contact_convergence.sh "$prm" "$out/$name" "$tolerance" |
    grep -E "resolved|quantity|_N |_us |_m_s "
done
python3 - "$out" <<'PY'
import csv, glob, os, sys
out = sys.argv[1]
lines = ["| case | levels | peak force (N) | hertz node | hertz midplane | "
         "duration (us) | node | midplane | departure (m/s) | node | midplane |",
         "|---|---|---|---|---|---|---|---|---|---|---|"]
for f in sorted(glob.glob(f"{out}/*/contact_convergence.csv")):
    rows = {r["quantity"]: r for r in csv.DictReader(open(f))}
    levels = [k.split("_")[3] for k in next(iter(rows.values()))
              if k.startswith("resolved_") and "_level_" in k]
    cells = [os.path.basename(os.path.dirname(f)), f"{levels[0]}-{levels[-1]}"]
    for q in ("peak_contact_force_N", "contact_duration_us",
              "departure_velocity_m_s"):
        r = rows[q]
        cells += [f"{float(r['resolved_converged']):.4g} ± "
                  f"{float(r['estimated_error']):.2g}",
                  f"{float(r['hertz_node_error_percent']):+.1f} %",
                  f"{float(r['hertz_midplane_error_percent']):+.1f} %"]
    lines.append("| " + " | ".join(cells) + " |")
open(f"{out}/table.md", "w").write("\n".join(lines) + "\n")
print("\n".join(lines))
PY
