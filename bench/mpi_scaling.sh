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
out=output/mpi_scaling
[ "${1:-}" = "--out" ] && out=$2
mkdir -p "$out/runs"
out=$(cd "$out" && pwd)
[ -x /usr/bin/time ] || apt-get install -y --no-install-recommends time
exe=$out/fgimpact_bench
cp "${FGIMPACT:-build/fgimpact}" "$exe"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
# Local ranks only: Open MPI 4 refuses to start without ssh/rsh on PATH
# (a fresh Debian has neither) unless the remote agent is unset.
export OMPI_MCA_plm_rsh_agent=

get() { awk -F' = ' -v k="$1" '$1 == k {print $2}' "$2"; }

csv=$out/results.csv
[ -n "${CASES:-}" ] && [ -f "$csv" ] || echo "id,study,path,ranks,mesh,n_dofs,n_time_steps,setup_s,factorization_s,time_per_step_ms,wall_time_s,elapsed_s,peak_rss_MB_largest_rank,peak_contact_force_N" > "$csv"

run() { # id study path ranks nx ny nz end_us
  local id=$1 study=$2 path=$3 ranks=$4 nx=$5 ny=$6 nz=$7 T=$8
  [[ "$id" =~ ${CASES:-.} ]] || return 0
  local dir=$out/runs/$id
  rm -rf "$dir"; mkdir -p "$dir"
  {
    echo "include $(pwd)/prm/default.prm"
    echo "subsection Geometry"
    echo "  set Subdivisions x = $nx"
    echo "  set Subdivisions y = $ny"
    echo "  set Subdivisions z = $nz"
    echo "end"
    echo "subsection Time integration"
    echo "  set End time = ${T}e-6"
    [ "$path" = explicit ] && echo "  set Scheme = explicit" && echo "  set Time step = 0"
    echo "end"
    echo "subsection Linear solver"
    case $path in
      cg_amg) echo "  set Type = cg"; echo "  set Preconditioner = amg" ;;
      mumps) echo "  set Type = mumps" ;;
      cholmod) echo "  set Type = cholmod" ;;
    esac
    echo "end"
    echo "subsection Output"
    echo "  set Directory    = $dir"
    echo "  set VTU interval = 0"
    echo "  set Log interval = 0"
    echo "end"
  } > "$dir/run.prm"
  printf '%-28s ranks %s %-11s ... ' "$id" "$ranks" "${nx}x${ny}x${nz}"
  local status=0
  timeout 1800 /usr/bin/time -v -o "$dir/time.txt" \
    mpirun -n "$ranks" "$exe" "$dir/run.prm" > "$dir/log.txt" 2>&1 || status=$?
  if [ ! -s "$dir/summary.txt" ]; then
    echo "FAILED (exit $status)"
    echo "$id,$study,$path,$ranks,${nx}x${ny}x${nz},,,,,,,,,failed" >> "$csv"
    return 0
  fi
  local s=$dir/summary.txt elapsed rss
  elapsed=$(awk -F': ' '/Elapsed \(wall clock\)/ {n = split($2, p, ":"); s = 0; for (i = 1; i <= n; ++i) s = 60 * s + p[i]; print s}' "$dir/time.txt")
  rss=$(awk -F': ' '/Maximum resident set size/ {printf "%.0f", $2 / 1024}' "$dir/time.txt")
  echo "$id,$study,$path,$ranks,${nx}x${ny}x${nz},$(get n_dofs $s),$(get n_time_steps $s),$(get setup_s $s),$(get factorization_s $s),$(get time_per_step_ms $s),$(get wall_time_s $s),$elapsed,$rss,$(get peak_contact_force_N $s)" >> "$csv"
  echo "$(get time_per_step_ms $s) ms/step, $rss MB"
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
