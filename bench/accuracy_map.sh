#!/usr/bin/env bash
# Speed/accuracy map of the default scene (issue 3): one knob at a time
# from prm/default.prm (mesh in-plane, mesh through the thickness, time
# step, element degree, property mode), each run's peak force, contact
# duration, departure velocity, max mid-plane deflection, wall time and
# peak RSS. Writes output/accuracy/results.csv and prints a Markdown table.
# Usage: bench/accuracy_map.sh   (about 5 minutes on 2 cores)
set -euo pipefail
cd "$(dirname "$0")/.."
exe=${FGIMPACT:-build/fgimpact}
[ -x /usr/bin/time ] || apt-get install -y --no-install-recommends time
root=output/accuracy
mkdir -p "$root"

# label | group | nx ny nz | degree | mode | dt
cases=(
  "inplane-20x10x4|in-plane|20 10 4|1|graded|1e-6"
  "inplane-40x20x4|in-plane|40 20 4|1|graded|1e-6"
  "inplane-80x40x4|in-plane|80 40 4|1|graded|1e-6"
  "inplane-160x80x4|in-plane|160 80 4|1|graded|1e-6"
  "thick-40x20x2|thickness|40 20 2|1|graded|1e-6"
  "thick-40x20x8|thickness|40 20 8|1|graded|1e-6"
  "thick-40x20x16|thickness|40 20 16|1|graded|1e-6"
  "dt-4us|time step|40 20 4|1|graded|4e-6"
  "dt-2us|time step|40 20 4|1|graded|2e-6"
  "dt-0.5us|time step|40 20 4|1|graded|0.5e-6"
  "Q2-20x10x2|degree|20 10 2|2|graded|1e-6"
  "Q2-40x20x4|degree|40 20 4|2|graded|1e-6"
  "homogeneous-40x20x4|property mode|40 20 4|1|homogeneous|1e-6"
  "pointwise-40x20x4|property mode|40 20 4|1|pointwise|1e-6"
)
keys="n_dofs peak_contact_force_N contact_duration_us departure_velocity_m_s max_midplane_deflection_um max_top_deflection_um wall_time_s"
echo "label,group,$(echo $keys | tr ' ' ','),peak_rss_MB" > "$root/results.csv"
printf '| run | knob | DoFs | peak force N | contact us | V_dep m/s | max W_mid um | max W_top um | wall s | peak RSS MB |\n|---|---|---|---|---|---|---|---|---|---|\n'
for c in "${cases[@]}"; do
  IFS='|' read -r label group mesh degree mode dt <<< "$c"
  read -r nx ny nz <<< "$mesh"
  dir=$root/$label
  mkdir -p "$dir"
  cat > "$dir/run.prm" <<PRM
include prm/default.prm
subsection Geometry
  set Subdivisions x = $nx
  set Subdivisions y = $ny
  set Subdivisions z = $nz
end
subsection Finite element
  set Degree = $degree
end
subsection Material
  set Property mode = $mode
end
subsection Time integration
  set Time step = $dt
end
subsection Output
  set Directory    = $dir/out
  set VTU interval = 0
  set Log interval = 0
end
PRM
  /usr/bin/time -v "$exe" "$dir/run.prm" > "$dir/log" 2> "$dir/time"
  rss=$(awk -F': ' '/Maximum resident set size/ {printf "%.0f", $2/1024}' "$dir/time")
  vals=()
  for k in $keys; do
    vals+=("$(awk -F' = ' -v k="$k" '$1 == k {print $2}' "$dir/out/summary.txt")")
  done
  (IFS=,; echo "$label,$group,${vals[*]},$rss") >> "$root/results.csv"
  printf '| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n' "$label" "$group" "${vals[@]}" "$rss"
done
