#!/bin/bash
# The default scene in a thermal environment (doc/thermal.md): prm/thermal.prm
# (Si3N4/SUS304, temperature-dependent, immovable sides, geometric
# stiffness) under a uniform temperature T = 300 K + Delta T, and its
# conduction case (ceramic face 600 K, metal face 300 K): the peak force,
# the contact duration, the ceramic tensile index of the impact's stress,
# the thermal stress at the face centres, the thermal buckling factor and
# the lowest frequency (a modal run of the same plate), one row per state.
#
#   scripts/thermal_scene.sh [BUILD_DIR] [DELTA_T ...]
#
# Defaults: build, Delta T = 0 300 600 900 1100 (the last near the thermal
# buckling of this thick plate, factor 1.13). Writes thermal_scene.csv in
# the working directory, and with Debian's python3-matplotlib
# thermal_scene.png (the four numbers against Delta T); runs in a
# temporary directory.
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$here/build}"
shift || true
deltas=("$@")
[ ${#deltas[@]} -gt 0 ] || deltas=(0 300 600 900 1100)
exe="$build/fgimpact"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
key() { sed -n "s/^$1 = //p" "$2/summary.txt"; }
row() { # name, extra -s options...
  local name="$1"; shift
  "$exe" "$here/prm/thermal.prm" -s "Output/Directory=$work/$name" \
    -s "Output/VTU interval=0" -s "Output/Report=false" "$@" > /dev/null
  "$exe" "$here/prm/thermal.prm" -s "Output/Directory=$work/${name}_modal" \
    -s "Problem type=modal" -s "Modal/Number of modes=1" \
    -s "Output/Report=false" "$@" > /dev/null
  local d="$work/$name" m="$work/${name}_modal"
  echo "$name,$(key peak_contact_force_N "$d"),$(key contact_duration_us "$d"),$(key max_principal_over_tensile_strength "$d"),$(key thermal_stress_top_MPa "$d"),$(key thermal_stress_bottom_MPa "$d"),$(key thermal_buckling_factor "$d"),$(key frequency_1_Hz "$m")"
}
{
  echo "state,peak_force_N,contact_duration_us,ceramic_index,thermal_stress_top_MPa,thermal_stress_bottom_MPa,buckling_factor,frequency_1_Hz"
  for dT in "${deltas[@]}"; do
    row "uniform_dT_$dT" -s "Thermal/Temperature field=uniform" \
      -s "Thermal/Temperature change=$dT"
  done
  row "conduction_600_300"
} | tee thermal_scene.csv

if /usr/bin/python3 -c "import matplotlib" 2> /dev/null; then
  /usr/bin/python3 - << 'PY'
import csv
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
rows = [r for r in csv.DictReader(open("thermal_scene.csv"))
        if r["state"].startswith("uniform_dT_")]
dT = [float(r["state"][len("uniform_dT_"):]) for r in rows]
fig, axes = plt.subplots(2, 2, figsize=(9, 6.5), sharex=True)
for ax, (key, label) in zip(axes.flat, [
        ("peak_force_N", "peak contact force (N)"),
        ("contact_duration_us", "contact duration (µs)"),
        ("ceramic_index", "ceramic tensile index (impact stress)"),
        ("frequency_1_Hz", "lowest frequency (Hz)")]):
    ax.plot(dT, [float(r[key]) for r in rows], "o-")
    ax.set_ylabel(label)
    ax.grid(True, alpha=0.3)
for ax in axes[1]:
    ax.set_xlabel("uniform Delta T above 300 K (K)")
fig.suptitle("prm/thermal.prm: Si3N4/SUS304, immovable sides, geometric stiffness")
fig.tight_layout()
fig.savefig("thermal_scene.png", dpi=110)
print("thermal_scene.png written")
PY
fi
