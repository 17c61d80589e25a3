#!/usr/bin/env bash
# The contact force that converges, beside the paper's law:
#
#   scripts/contact_convergence.sh SCENE.prm [OUT_DIR] [TOLERANCE] [FIRST] [LAST]
#
# runs SCENE with Contact/Model = resolved sphere at Geometry/Contact
# refinement levels FIRST, FIRST+1, ... (default 3 .. 7) until the peak
# force changes by less than TOLERANCE (default 0.01 = 1 %), extrapolates
# the peak force, contact duration and departure velocity (Richardson,
# with the order observed on the last three levels when their changes
# shrink), and runs the same scene with the paper's hertz node (the
# scene's own mesh) and with hertz midplane (at the last level); prints a
# table with each model's error against the extrapolated resolved values
# and writes OUT_DIR/contact_convergence.csv and, if matplotlib is there,
# OUT_DIR/contact_force.png with the three contact-force histories.
# Run from the repository root (the .prm's includes are read from there).
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/fgimpact_lib.sh

scene=${1:?usage: scripts/contact_convergence.sh SCENE.prm [OUT_DIR] [TOLERANCE] [FIRST] [LAST]}
out=${2:-output/contact_convergence/$(basename "$scene" .prm)}
tolerance=${3:-0.01}
first=${4:-3}
last=${5:-7}
exe=${FGIMPACT:-build/fgimpact}
mkdir -p "$out"
keys="peak_contact_force_N contact_duration_us departure_velocity_m_s"

run() { # run NAME MODEL LEVELS
  local dir=$out/$1
  write_prm "$out/$1.prm" "$scene" "Contact/Model=$2" \
    "Geometry/Contact refinement levels=$3" "Output/Directory=$dir" \
    "Output/VTU interval=0" "Output/Log interval=0"
  local start=$SECONDS
  "$exe" "$out/$1.prm" > "$out/$1.log" 2>&1 ||
    { echo "fgimpact failed on $out/$1.prm (see $out/$1.log)" >&2; exit 1; }
  printf '%-18s level %d: %s N, %s s, %s DoFs\n' "$2" "$3" \
    "$(summary_value "$dir" peak_contact_force_N)" $((SECONDS - start)) \
    "$(summary_value "$dir" n_dofs)"
}

levels=()
previous=""
for ((level = first; level <= last; ++level)); do
  run "resolved_$level" "resolved sphere" "$level"
  levels+=("$level")
  force=$(summary_value "$out/resolved_$level" peak_contact_force_N)
  if [ -n "$previous" ] &&
    python3 -c "import sys; sys.exit(0 if abs($force/$previous-1) < $tolerance else 1)"; then
    break
  fi
  previous=$force
done
top=${levels[-1]}
run hertz_node "hertz node" 0
run hertz_midplane "hertz midplane" "$top"

python3 - "$out" "$keys" "${levels[@]}" <<'PY'
import math, sys
out, keys, levels = sys.argv[1], sys.argv[2].split(), sys.argv[3:]

def summary(name):
    values = {}
    for line in open(f"{out}/{name}/summary.txt"):
        if " = " in line and not line.startswith("#"):
            k, v = line.split(" = ", 1)
            values[k.strip()] = v.strip()
    return values

def number(s):
    try:
        return float(s)
    except ValueError:
        return float("nan")

resolved = [summary(f"resolved_{l}") for l in levels]
rows = []
for key in keys:
    f = [number(r[key]) for r in resolved]
    best, order, estimate = f[-1], float("nan"), f[-1]
    if len(f) >= 3:
        d1, d2 = f[-2] - f[-3], f[-1] - f[-2]
        if d1 * d2 > 0 and abs(d1) > abs(d2):
            order = math.log2(d1 / d2)
            estimate = f[-1] + d2 / (2 ** order - 1)
    error = abs(estimate - best)
    if error == 0 and len(f) >= 2:
        error = abs(f[-1] - f[-2])  # no order observed: the last change
    rows.append((key, f, order, estimate, error))

node, mid = summary("hertz_node"), summary("hertz_midplane")
with open(f"{out}/contact_convergence.csv", "w") as csv:
    csv.write("quantity," + ",".join(f"resolved_level_{l}" for l in levels) +
              ",observed_order,resolved_extrapolated,estimated_error,"
              "hertz_node,hertz_node_error_percent,hertz_midplane,"
              "hertz_midplane_error_percent\n")
    print(f"\n{'quantity':<24}" + "".join(f"{'level ' + l:>12}" for l in levels) +
          f"{'order':>7}{'extrapolated':>14}{'+-':>9}{'hertz node':>12}{'err %':>8}"
          f"{'midplane':>11}{'err %':>8}")
    for key, f, order, estimate, error in rows:
        n, m = number(node[key]), number(mid[key])
        en, em = 100 * (n / estimate - 1), 100 * (m / estimate - 1)
        print(f"{key:<24}" + "".join(f"{x:12.4f}" for x in f) +
              f"{order:7.2f}{estimate:14.4f}{error:9.4f}{n:12.4f}{en:8.2f}"
              f"{m:11.4f}{em:8.2f}")
        csv.write(f"{key}," + ",".join(f"{x:.6g}" for x in f) +
                  f",{order:.3f},{estimate:.6g},{error:.3g},{n:.6g},{en:.3f},"
                  f"{m:.6g},{em:.3f}\n")
PY

# The figure, if matplotlib is installed (Debian's python3-matplotlib).
/usr/bin/python3 - "$out" "$top" <<'PY' || echo "(no figure: python3-matplotlib missing)"
import csv, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
out, top = sys.argv[1], sys.argv[2]
plt.figure(figsize=(6, 4))
for name, label in ((f"resolved_{top}", f"resolved sphere, level {top}"),
                    ("hertz_midplane", "hertz midplane"),
                    ("hertz_node", "hertz node (paper)")):
    rows = list(csv.reader(open(f"{out}/{name}/history.csv")))
    head = [h.strip() for h in rows[0]]
    t, F = head.index("t_us"), head.index("contact_force_N")
    plt.plot([float(r[t]) for r in rows[1:]], [float(r[F]) for r in rows[1:]],
             label=label)
plt.xlabel("t (us)"); plt.ylabel("contact force (N)"); plt.legend()
plt.tight_layout(); plt.savefig(f"{out}/contact_force.png", dpi=120)
print(f"figure: {out}/contact_force.png")
PY
echo "results in $out"
