#!/usr/bin/env bash
# Mesh study of the default scene (prm/default.prm): runs it on several
# meshes and prints a Markdown table of the summary values.  Used for
# doc/mesh_study.md.  Usage: scripts/mesh_study.sh [nx:ny:nz ...]
set -euo pipefail
cd "$(dirname "$0")/.."
exe=${FGIMPACT:-build/fgimpact}
meshes=("$@")
[ ${#meshes[@]} -gt 0 ] || meshes=(20:10:2 40:20:2 40:20:4 40:20:8 80:40:4 80:40:8)
root=output/mesh_study
mkdir -p "$root"
keys="n_dofs peak_contact_force_N time_of_peak_force_us contact_duration_us departure_velocity_m_s max_indentation_um max_midplane_deflection_um max_top_deflection_um max_relative_energy_drift wall_time_s"
printf '| mesh |'; for k in $keys; do printf ' %s |' "$k"; done; printf '\n|---|'
for k in $keys; do printf -- '---|'; done; printf '\n'
for m in "${meshes[@]}"; do
  IFS=: read -r nx ny nz <<< "$m"
  dir=$root/${nx}x${ny}x${nz}
  prm=$root/${nx}x${ny}x${nz}.prm
  cat > "$prm" <<PRM
include prm/default.prm
subsection Geometry
  set Subdivisions x = $nx
  set Subdivisions y = $ny
  set Subdivisions z = $nz
end
subsection Output
  set Directory    = $dir
  set VTU interval = 0
  set Log interval = 0
end
PRM
  "$exe" "$prm" > "$root/${nx}x${ny}x${nz}.log"
  printf '| %sx%sx%s |' "$nx" "$ny" "$nz"
  for k in $keys; do
    printf ' %s |' "$(awk -F' = ' -v k="$k" '$1 == k {print $2}' "$dir/summary.txt")"
  done
  printf '\n'
done
