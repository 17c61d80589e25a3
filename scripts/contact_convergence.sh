#!/usr/bin/env bash
# The contact force that converges, beside the paper's law:
#
#   scripts/contact_convergence.sh SCENE.prm [OUT_DIR] [TOLERANCE]
#
# A thin wrapper over the program: SCENE with Contact/Model = resolved
# sphere and Accuracy = converged (Accuracy tolerance = TOLERANCE, default
# 0.01: the program runs the contact refinement levels from the scene's
# automatic one until the peak force, contact duration, departure
# velocity, mid-plane deflection and indentation change by less than it,
# then halves the time step once, and writes convergence.csv and an error
# estimate per number in summary.txt), then the same scene with the
# paper's hertz node (the scene's own mesh) and with hertz midplane (at the
# converged level).  Prints a table with each model's error against the
# converged resolved values and writes OUT_DIR/contact_convergence.csv
# and, if matplotlib is there, OUT_DIR/contact_force.png with the three
# contact-force histories.  Run from the repository root.
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/fgimpact_lib.sh

scene=${1:?usage: scripts/contact_convergence.sh SCENE.prm [OUT_DIR] [TOLERANCE]}
out=${2:-output/contact_convergence/$(basename "$scene" .prm)}
tolerance=${3:-0.01}
exe=${FGIMPACT:-build/fgimpact}
mkdir -p "$out"

run() { # run NAME [PATH=VALUE ...]
  local name=$1 dir=$out/$1
  shift
  write_prm "$out/$name.prm" "$scene" "$@" "Output/Directory=$dir" \
    "Output/VTU interval=0" "Output/Log interval=0"
  local start=$SECONDS
  "$exe" "$out/$name.prm" > "$out/$name.log" 2>&1 ||
    { echo "fgimpact failed on $out/$name.prm (see $out/$name.log)" >&2; exit 1; }
  printf '%-16s %s N, %s s, %s DoFs\n' "$name" \
    "$(summary_value "$dir" peak_contact_force_N)" $((SECONDS - start)) \
    "$(summary_value "$dir" n_dofs)"
}

# The four global numbers only: a probe's peak stress on a face converges
# at first order with the base mesh and would refuse 1 %.
run resolved "Contact/Model=resolved sphere" "Accuracy=converged" \
  "Accuracy tolerance=$tolerance" "Output/Probe points="
top=$(summary_value "$out/resolved" converged_contact_refinement_levels)
run hertz_node "Contact/Model=hertz node"
run hertz_midplane "Contact/Model=hertz midplane" \
  "Geometry/Contact refinement levels=$top"

python3 - "$out" <<'PY'
import csv, sys
out = sys.argv[1]
keys = [("peak_contact_force_N", "peak_contact_force"),
        ("contact_duration_us", "contact_duration"),
        ("departure_velocity_m_s", "departure_velocity"),
        ("max_midplane_deflection_um", "max_midplane_deflection")]

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

levels = list(csv.DictReader(open(f"{out}/resolved/convergence.csv")))
resolved, node, mid = summary("resolved"), summary("hertz_node"), summary("hertz_midplane")
header = ("quantity," + ",".join(f"resolved_{r['subdivisions_x']}x{r['subdivisions_y']}"
                                 f"x{r['subdivisions_z']}_level_"
                                 f"{r['contact_refinement_levels']}"
                                 f"_dt_{r['time_step_us']}" for r in levels) +
          ",resolved_converged,estimated_error,error_method,hertz_node,"
          "hertz_node_error_percent,hertz_midplane,hertz_midplane_error_percent\n")
with open(f"{out}/contact_convergence.csv", "w") as f:
    f.write(header)
    print(f"\n{'quantity':<28}{'resolved':>12}{'+-':>10}{'hertz node':>12}"
          f"{'err %':>8}{'midplane':>11}{'err %':>8}   (error estimate method)")
    for column, key in keys:
        best = number(resolved[column])
        error = best * number(resolved[f"{key}_error_estimate"])
        n, m = number(node[column]), number(mid[column])
        en, em = 100 * (n / best - 1), 100 * (m / best - 1)
        how = resolved[f"{key}_error_method"]
        print(f"{column:<28}{best:12.4f}{error:10.4f}{n:12.4f}{en:8.2f}"
              f"{m:11.4f}{em:8.2f}   ({how})")
        f.write(f"{column}," + ",".join(r[column] for r in levels) +
                f",{best:.8g},{error:.3g},{how},{n:.8g},{en:.3f},{m:.8g},{em:.3f}\n")
PY

# The figure, if matplotlib is installed (Debian's python3-matplotlib).
/usr/bin/python3 - "$out" "$top" <<'PY' || echo "(no figure: python3-matplotlib missing)"
import csv, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
out, top = sys.argv[1], sys.argv[2]
plt.figure(figsize=(6, 4))
for name, label in (("resolved", f"resolved sphere, level {top}, converged"),
                    ("hertz_midplane", "hertz midplane"),
                    ("hertz_node", "hertz node (paper)")):
    rows = list(csv.DictReader(open(f"{out}/{name}/history.csv")))
    plt.plot([float(r["t_us"]) for r in rows],
             [float(r["contact_force_N"]) for r in rows], label=label)
plt.xlabel("t (µs)"); plt.ylabel("contact force (N)"); plt.legend()
plt.tight_layout(); plt.savefig(f"{out}/contact_force.png", dpi=120)
print(f"figure: {out}/contact_force.png")
PY
echo "results in $out"
