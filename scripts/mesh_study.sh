#!/usr/bin/env bash
# Mesh study of the default scene (prm/default.prm): runs it on several
# meshes and prints a Markdown table of the summary values.  Used for
# doc/mesh_study.md.  Usage: scripts/mesh_study.sh [nx:ny:nz ...]
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/fgimpact_lib.sh
exe=${FGIMPACT:-build/fgimpact}
meshes=("$@")
[ ${#meshes[@]} -gt 0 ] || meshes=(20:10:2 40:20:2 40:20:4 40:20:8 80:40:4 80:40:8)
root=output/mesh_study
mkdir -p "$root"
keys="n_dofs peak_contact_force_N time_of_peak_force_us contact_duration_us departure_velocity_m_s max_approach_um max_midplane_deflection_um max_top_deflection_um max_relative_energy_drift wall_time_s"
printf '| mesh |'; for k in $keys; do printf ' %s |' "$k"; done; printf '\n|---|'
for k in $keys; do printf -- '---|'; done; printf '\n'
for m in "${meshes[@]}"; do
  IFS=: read -r nx ny nz <<< "$m"
  dir=$root/${nx}x${ny}x${nz}
  prm=$root/${nx}x${ny}x${nz}.prm
  write_prm "$prm" prm/default.prm "Geometry/Symmetry=none" \
    "Geometry/Subdivisions x=$nx" "Geometry/Subdivisions y=$ny" \
    "Geometry/Subdivisions z=$nz" \
    "Output/Directory=$dir" "Output/VTU interval=0" "Output/Log interval=0"
  "$exe" "$prm" > "$root/${nx}x${ny}x${nz}.log"
  printf '| %sx%sx%s |' "$nx" "$ny" "$nz"
  for k in $keys; do
    printf ' %s |' "$(summary_value "$dir" "$k")"
  done
  printf '\n'
done
