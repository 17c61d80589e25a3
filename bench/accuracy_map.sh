#!/usr/bin/env bash
# Speed/accuracy map of the default scene (issue 3): one knob at a time
# from prm/default.prm, plus the cross terms that the presets need:
#  - in plane (Q1, nz = 4): 20x10, 40x20, 80x40, 160x80;
#  - through the thickness (Q1, 40x20): nz = 2, 4, 8, 16, 32;
#  - time step on 40x20x4 and on 40x20x8: dt = 4, 2, 1, 0.5, 0.25 us;
#  - degree x mesh: Q2 on 10x5x2, 20x10x2, 20x10x4, 40x20x4; Q1 with the
#    same elements (20x10x2, 20x10x4, 40x20x4; Q1 10x5x2 has no node at the
#    plate centre) and with the same node spacing (20x10x4, 40x20x4,
#    40x20x8, 80x40x8);
#  - property mode (all three) on 40x20x4;
#  - the Accuracy presets (fast, standard, accurate) through the .prm entry
#    itself; each repeats a run above (the CSV's mesh and dt columns give
#    what the preset sets, and the script checks the log says so).
# Each distinct run is made once. Records each run's peak force, contact
# duration, departure velocity, max indentation, mid-plane and top
# deflections, impulse, wall time, time per step and peak RSS (GNU time).
# Writes output/accuracy/results.csv and prints a Markdown table;
# bench/plot_accuracy.py draws the figures from the CSV.
# Usage: bench/accuracy_map.sh   (about 8 minutes on 2 shared cores;
#        FGIMPACT=path/to/fgimpact to use another executable)
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/fgimpact_lib.sh
exe=${FGIMPACT:-build/fgimpact}
need_gnu_time
root=output/accuracy
mkdir -p "$root"

# label | group | nx ny nz | degree | mode | dt (s) [| Accuracy preset]
cases=(
  "inplane-20x10x4|in-plane|20 10 4|1|graded|1e-6"
  "inplane-40x20x4|in-plane|40 20 4|1|graded|1e-6"
  "inplane-80x40x4|in-plane|80 40 4|1|graded|1e-6"
  "inplane-160x80x4|in-plane|160 80 4|1|graded|1e-6"
  "thick-40x20x2|thickness|40 20 2|1|graded|1e-6"
  "thick-40x20x8|thickness|40 20 8|1|graded|1e-6"
  "thick-40x20x16|thickness|40 20 16|1|graded|1e-6"
  "thick-40x20x32|thickness|40 20 32|1|graded|1e-6"
  "dt-4us|time step|40 20 4|1|graded|4e-6"
  "dt-2us|time step|40 20 4|1|graded|2e-6"
  "dt-0.5us|time step|40 20 4|1|graded|0.5e-6"
  "dt-0.25us|time step|40 20 4|1|graded|0.25e-6"
  "dt-4us-40x20x8|time step 40x20x8|40 20 8|1|graded|4e-6"
  "dt-2us-40x20x8|time step 40x20x8|40 20 8|1|graded|2e-6"
  "dt-0.5us-40x20x8|time step 40x20x8|40 20 8|1|graded|0.5e-6"
  "dt-0.25us-40x20x8|time step 40x20x8|40 20 8|1|graded|0.25e-6"
  "Q2-10x5x2|degree|10 5 2|2|graded|1e-6"
  "Q2-20x10x2|degree|20 10 2|2|graded|1e-6"
  "Q2-20x10x4|degree|20 10 4|2|graded|1e-6"
  "Q2-40x20x4|degree|40 20 4|2|graded|1e-6"
  "Q1-20x10x2|degree|20 10 2|1|graded|1e-6"
  "Q1-80x40x8|degree|80 40 8|1|graded|1e-6"
  "homogeneous-40x20x4|property mode|40 20 4|1|homogeneous|1e-6"
  "pointwise-40x20x4|property mode|40 20 4|1|pointwise|1e-6"
  "preset-fast|preset|40 20 2|1|graded|2e-6|fast"
  "preset-standard|preset|40 20 4|1|graded|1e-6|standard"
  "preset-accurate|preset|40 20 16|1|graded|1e-6|accurate"
)
keys="n_dofs peak_contact_force_N contact_duration_us departure_velocity_m_s max_indentation_um max_midplane_deflection_um max_top_deflection_um impulse_N_s time_per_step_ms wall_time_s"
echo "label,group,nx,ny,nz,degree,mode,dt_us,$(echo $keys | tr ' ' ','),peak_rss_MB" > "$root/results.csv"
printf '| run | knob | DoFs | peak force N | contact us | V_dep m/s | max W_mid um | max W_top um | wall s | peak RSS MB |\n|---|---|---|---|---|---|---|---|---|---|\n'
for c in "${cases[@]}"; do
  IFS='|' read -r label group mesh degree mode dt preset <<< "$c"
  read -r nx ny nz <<< "$mesh"
  dir=$root/$label
  mkdir -p "$dir"
  write_prm "$dir/run.prm" prm/default.prm "Accuracy=${preset:-custom}" \
    "Geometry/Symmetry=none" \
    "Geometry/Subdivisions x=$nx" "Geometry/Subdivisions y=$ny" \
    "Geometry/Subdivisions z=$nz" "Finite element/Degree=$degree" \
    "Material/Property mode=$mode" "Time integration/Time step=$dt" \
    "Output/Directory=$dir/out" "Output/VTU interval=0" "Output/Log interval=0"
  /usr/bin/time -v "$exe" "$dir/run.prm" > "$dir/log" 2> "$dir/time"
  if [ -n "${preset:-}" ] && ! grep -q "Accuracy = $preset sets Geometry/Subdivisions x, y, z = $nx, $ny, $nz .*Time step = $(awk -v d="$dt" 'BEGIN {print d * 1e6}') us" "$dir/log"; then
    echo "accuracy_map.sh: $label: the preset did not set $nx x $ny x $nz, dt = $dt s (see $dir/log)" >&2
    exit 1
  fi
  rss=$(gnu_time_rss_mb "$dir/time")
  declare -A v=()
  for k in $keys; do
    v[$k]=$(summary_value "$dir/out" "$k")
  done
  dt_us=$(awk -v d="$dt" 'BEGIN {print d * 1e6}')
  vals=()
  for k in $keys; do vals+=("${v[$k]}"); done
  (IFS=,; echo "$label,$group,$nx,$ny,$nz,$degree,$mode,$dt_us,${vals[*]},$rss") >> "$root/results.csv"
  printf '| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n' "$label" "$group" \
    "${v[n_dofs]}" "${v[peak_contact_force_N]}" "${v[contact_duration_us]}" \
    "${v[departure_velocity_m_s]}" "${v[max_midplane_deflection_um]}" \
    "${v[max_top_deflection_um]}" "${v[wall_time_s]}" "$rss"
  unset v
done
