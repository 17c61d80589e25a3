#!/usr/bin/env bash
# MPI scaling of fgimpact (issue 5): the default scene (prm/default.prm)
# on 1 and 2 ranks of this machine.
#   strong scaling: 89,667 DoFs (80x40x8) and 1,035,351 DoFs (200x100x16),
#                   explicit (lumped mass), implicit CG + AMG, implicit
#                   MUMPS (89,667 only; 1 rank CHOLMOD for reference);
#   weak scaling:   89,667 DoFs on 1 rank against 178,227 DoFs (160x40x8)
#                   on 2 ranks.
# The figure of merit is the program's time per step (summary.txt); short
# end times, because it does not depend on the number of steps.  Peak RSS
# from GNU time (for mpirun: the largest rank).
#
#   bench/mpi_scaling.sh [--out DIR]      (about 15 minutes)
#   CASES=regex bench/mpi_scaling.sh     only the runs whose id matches
#                                         (rows are appended to results.csv)
#
# Results: DIR/results.csv; table and plot with
#   /usr/bin/python3 bench/plot_mpi_scaling.py DIR/results.csv
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/fgimpact_lib.sh
out=output/mpi_scaling
[ "${1:-}" = "--out" ] && out=$2
mkdir -p "$out/runs"
out=$(cd "$out" && pwd)
need_gnu_time
exe=$(copy_executable "$out")
allow_local_mpirun

csv=$out/results.csv
[ -n "${CASES:-}" ] && [ -f "$csv" ] || echo "id,study,path,ranks,mesh,n_dofs,n_time_steps,setup_s,factorization_s,time_per_step_ms,wall_time_s,elapsed_s,peak_rss_MB_largest_rank,peak_contact_force_N" > "$csv"

run() { # id study path ranks nx ny nz end_us
  local id=$1 study=$2 path=$3 ranks=$4 nx=$5 ny=$6 nz=$7 T=$8
  [[ "$id" =~ ${CASES:-.} ]] || return 0
  local dir=$out/runs/$id
  rm -rf "$dir"; mkdir -p "$dir"
  local -a overrides=("Geometry/Subdivisions x=$nx" "Geometry/Subdivisions y=$ny"
    "Geometry/Subdivisions z=$nz" "Time integration/End time=${T}e-6")
  case $path in
    explicit) overrides+=("Time integration/Scheme=explicit" "Time integration/Time step=0") ;;
    cg_amg) overrides+=("Linear solver/Type=cg" "Linear solver/Preconditioner=amg") ;;
    mumps|cholmod) overrides+=("Linear solver/Type=$path") ;;
  esac
  # mpirun starts the ranks in this directory (the repository root), where
  # the relative include of prm/default.prm is opened.
  write_prm "$dir/run.prm" prm/default.prm "Geometry/Symmetry=none" "${overrides[@]}" \
    "Output/Directory=$dir" "Output/VTU interval=0" "Output/Log interval=0"
  printf '%-28s ranks %s %-11s ... ' "$id" "$ranks" "${nx}x${ny}x${nz}"
  local status=0
  timeout 1800 /usr/bin/time -v -o "$dir/time.txt" \
    mpirun -n "$ranks" "$exe" "$dir/run.prm" > "$dir/run.log" 2>&1 || status=$?
  if [ ! -s "$dir/summary.txt" ]; then
    echo "FAILED (exit $status)"
    echo "$id,$study,$path,$ranks,${nx}x${ny}x${nz},,,,,,,,,failed" >> "$csv"
    return 0
  fi
  local elapsed rss row=$id,$study,$path,$ranks,${nx}x${ny}x${nz} k
  elapsed=$(gnu_time_elapsed_s "$dir/time.txt")
  rss=$(gnu_time_rss_mb "$dir/time.txt")
  for k in n_dofs n_time_steps setup_s factorization_s time_per_step_ms wall_time_s; do
    row+=,$(summary_value "$dir" $k)
  done
  echo "$row,$elapsed,$rss,$(summary_value "$dir" peak_contact_force_N)" >> "$csv"
  echo "$(summary_value "$dir" time_per_step_ms) ms/step, $rss MB"
}

# Strong scaling, ~1e5 DoFs.
run s1e5-explicit-1 strong explicit 1 80 40 8 20
run s1e5-explicit-2 strong explicit 2 80 40 8 20
run s1e5-cg_amg-1   strong cg_amg   1 80 40 8 10
run s1e5-cg_amg-2   strong cg_amg   2 80 40 8 10
run s1e5-mumps-1    strong mumps    1 80 40 8 20
run s1e5-mumps-2    strong mumps    2 80 40 8 20
run s1e5-cholmod-1  strong cholmod  1 80 40 8 20
# Strong scaling, ~1e6 DoFs.
run s1e6-explicit-1 strong explicit 1 200 100 16 3
run s1e6-explicit-2 strong explicit 2 200 100 16 3
run s1e6-cg_amg-1   strong cg_amg   1 200 100 16 4
run s1e6-cg_amg-2   strong cg_amg   2 200 100 16 4
# Weak scaling: twice the DoFs on twice the ranks.
run w-explicit-2    weak   explicit 2 160 40 8 20
run w-cg_amg-2      weak   cg_amg   2 160 40 8 10
echo "results: $csv"
