#!/usr/bin/env bash
# Performance benchmark of fgimpact (issue 4): the default scene
# (prm/default.prm) on 6 meshes from 12,915 to 1,035,351 DoFs, for every
# solver path, with the peak RSS of every run from GNU time.
#
#   bench/run_benchmark.sh [--quick] [--slow] [--out DIR]
#
#   --quick   only the two smallest meshes (about 2.5 minutes; all: 23 min)
#   --slow    also the rows skipped by default for time (KLU on 89,667 DoFs)
#   --out DIR results directory (default output/bench)
#
# The executable is $FGIMPACT (default build/fgimpact); it is copied to
# DIR/fgimpact_bench first, so that a rebuild during the benchmark does not
# change it.  Every run gets DIR/runs/<id>/{run.prm,run.log (stdout; fgimpact writes its own log.txt too),time.txt,summary.txt}.
# Results: DIR/results.csv and DIR/results.md (Markdown table); plots with
#   /usr/bin/python3 bench/plot_benchmark.py DIR/results.csv
#
# What a row measures: the program's own timers (summary.txt: setup_s,
# factorization_s, time_per_step_ms, and spmv_ms / solve_ms, one SpMV with
# the step's matrix and one solve with the effective matrix, both measured
# inside the same run), and GNU time's elapsed wall time and maximum RSS of
# the process.  Large meshes run a shorter End time: the figure of merit is
# the time per step, which does not depend on the number of steps
# (projected_400us_s extrapolates the whole run).  The full time (400 us
# at the default dt) is used where it is affordable; only full runs give
# the contact duration and the departure velocity.
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/fgimpact_lib.sh

quick=0
slow=0
out=output/bench
while [ $# -gt 0 ]; do
  case "$1" in
    --quick) quick=1 ;;
    --slow) slow=1 ;;
    --out) out=$2; shift ;;
    -h|--help) sed -n '2,26p' "$0"; exit 0 ;;
    *) echo "unknown option $1 (see --help)" >&2; exit 1 ;;
  esac
  shift
done

need_gnu_time   # for the peak RSS
mkdir -p "$out/runs"
out=$(cd "$out" && pwd)
exe_src=${FGIMPACT:-build/fgimpact}
exe=$(copy_executable "$out")

# ----------------------------------------------------------------- cases
# Meshes (even subdivisions: a node under the central impact).
#   label      nx  ny  nz  DoFs
meshes=(
  "40x20x4    40  20  4"    # 12,915 (the default mesh)
  "80x40x4    80  40  4"    # 49,815
  "80x40x8    80  40  8"    # 89,667
  "120x60x8   120 60  8"    # 199,287
  "160x80x16  160 80  16"   # 665,091
  "200x100x16 200 100 16"   # 1,035,351
)
[ $quick -eq 1 ] && meshes=("${meshes[@]:0:2}")

# Solver paths: id, scheme, solver type, preconditioner.
paths=(
  "cholmod  implicit cholmod -"
  "cg_jacobi implicit cg     jacobi"
  "cg_amg   implicit cg      amg"
  "klu      implicit klu     -"
  "mumps    implicit mumps   -"
  "explicit explicit -       -"
)

# End time in us per path and mesh, or "skip:<reason>".  Chosen from
# trial runs so that each row takes at most ~3 minutes: the full 400 us
# where affordable, 5-100 us otherwise.
end_time() { # path mesh
  case "$1:$2" in
    cholmod:40x20x4|cholmod:80x40x4|cholmod:80x40x8) echo 400 ;;
    cholmod:120x60x8) echo 100 ;;
    cholmod:160x80x16) echo 20 ;;
    cholmod:200x100x16) echo "skip:memory: the supernodal factor would need about 19 GB (peak RSS 2.3 GB at 199,287 and 10.6 GB at 665,091 DoFs, growing as N^1.28), over the 20 GiB budget on a shared 24 GiB machine; factorization about 330 s" ;;
    cg_jacobi:40x20x4) echo 400 ;;
    cg_jacobi:80x40x4) echo 100 ;;
    cg_jacobi:80x40x8) echo 40 ;;
    cg_jacobi:120x60x8) echo 20 ;;
    cg_jacobi:160x80x16|cg_jacobi:200x100x16) echo 10 ;;
    cg_amg:40x20x4) echo 40 ;;
    cg_amg:80x40x4) echo 20 ;;
    cg_amg:80x40x8) echo 10 ;;
    cg_amg:*) echo 5 ;;
    klu:40x20x4) echo 400 ;;
    klu:80x40x4) echo 20 ;;
    klu:80x40x8)
      if [ $slow -eq 1 ]; then echo 10
      else echo "skip:time: KLU factorization 293 s on this mesh in a separate run (5 min for 10 steps); run with --slow"; fi ;;
    klu:*) echo "skip:time: KLU factorization would take far over 10 minutes (1.5 s at 12,915, 19 s at 49,815, 293 s at 89,667 DoFs)" ;;
    mumps:40x20x4) echo 400 ;;
    mumps:80x40x4) echo 20 ;;
    mumps:80x40x8) echo 10 ;;
    mumps:*) echo "skip:not a required path; the direct solver comparison uses CHOLMOD at these sizes" ;;
    explicit:160x80x16) echo 100 ;;
    explicit:200x100x16) echo 40 ;;
    explicit:*) echo 400 ;;
  esac
}

# ------------------------------------------------------------ one run
csv=$out/results.csv
echo "id,group,scheme,solver,preconditioner,mesh,n_dofs,end_time_us,n_time_steps,dt_us,setup_s,factorization_s,time_per_step_ms,spmv_ms,solve_ms,step_per_spmv,step_per_solve,time_loop_s,output_s,wall_time_s,elapsed_s,projected_400us_s,peak_rss_MB,peak_contact_force_N,contact_duration_us,departure_velocity_m_s,max_newton_iterations,exit_status,note" > "$csv"

csv_quote() { # a CSV field in double quotes
  printf '"%s"' "$(printf '%s' "$1" | sed 's/"/""/g')"
}

run_case() { # id group scheme solver precond nx ny nz end_us [Section/Entry=value ...]
  local id=$1 group=$2 scheme=$3 solver=$4 precond=$5 nx=$6 ny=$7 nz=$8 T=$9
  shift 9
  local dir=$out/runs/$id
  local mesh=${nx}x${ny}x${nz}
  rm -rf "$dir"
  mkdir -p "$dir"
  local -a overrides=("Geometry/Subdivisions x=$nx" "Geometry/Subdivisions y=$ny"
    "Geometry/Subdivisions z=$nz" "Time integration/Scheme=$scheme"
    "Time integration/End time=${T}e-6")
  if [ "$scheme" = explicit ]; then
    overrides+=("Time integration/Time step=0")
  else
    overrides+=("Linear solver/Type=$solver")
    [ "$precond" != - ] && overrides+=("Linear solver/Preconditioner=$precond")
  fi
  write_prm "$dir/run.prm" prm/default.prm "Geometry/Symmetry=none" "${overrides[@]}" "$@" \
    "Output/Instrumentation=true" "Output/Directory=$dir" "Output/VTU interval=0" "Output/Log interval=0"

  printf '%-34s %-11s %7s us ... ' "$id" "$mesh" "$T"
  local status=0
  # 20 minutes hard limit per run (none of the planned rows comes close).
  timeout 1200 /usr/bin/time -v -o "$dir/time.txt" "$exe" "$dir/run.prm" \
    > "$dir/run.log" 2>&1 || status=$?
  local note=""
  if [ ! -s "$dir/summary.txt" ]; then
    note="failed (exit $status): $(grep -m1 -iE 'error|exception|what' "$dir/run.log" | cut -c1-150)"
    echo "FAILED (exit $status)"
    echo "$id,$group,$scheme,$solver,$precond,$mesh,,$T,,,,,,,,,,,,,,,,,,,,$status,$(csv_quote "$note")" >> "$csv"
    return 0
  fi
  [ $status -eq 139 ] && note="segfault at exit (Amesos_Mumps destructor) after summary.txt was written"
  [ $status -ne 0 ] && [ -z "$note" ] && note="exit status $status"

  local n_dofs n_steps setup fact tps spmv solve loop output wall fmax tc vdep newton
  n_dofs=$(summary_value "$dir" n_dofs); n_steps=$(summary_value "$dir" n_time_steps)
  setup=$(summary_value "$dir" setup_s); fact=$(summary_value "$dir" factorization_s)
  tps=$(summary_value "$dir" time_per_step_ms); spmv=$(summary_value "$dir" spmv_ms)
  solve=$(summary_value "$dir" solve_ms); loop=$(summary_value "$dir" time_loop_s)
  output=$(summary_value "$dir" output_s); wall=$(summary_value "$dir" wall_time_s)
  fmax=$(summary_value "$dir" peak_contact_force_N)
  tc=$(summary_value "$dir" contact_duration_us)
  vdep=$(summary_value "$dir" departure_velocity_m_s)
  newton=$(summary_value "$dir" max_newton_iterations)
  local elapsed rss_mb dt
  elapsed=$(gnu_time_elapsed_s "$dir/time.txt")
  rss_mb=$(gnu_time_rss_mb "$dir/time.txt" %.1f)
  dt=$(sed -n 's/.*; dt = \([0-9.e+-]*\) us.*/\1/p' "$dir/run.log" | head -1)
  # dt from the step count when stdout was lost (the MUMPS crash at exit).
  [ -z "$dt" ] && dt=$(awk -v T="$T" -v n="$n_steps" 'BEGIN {printf "%.6g", T / n}')
  awk -v id="$id" -v group="$group" -v scheme="$scheme" -v solver="$solver" \
      -v precond="$precond" -v mesh="$mesh" -v n_dofs="$n_dofs" -v T="$T" \
      -v n_steps="$n_steps" -v dt="$dt" -v setup="$setup" -v fact="$fact" \
      -v tps="$tps" -v spmv="$spmv" -v solve="$solve" -v loop="$loop" \
      -v output="$output" -v wall="$wall" -v elapsed="$elapsed" \
      -v rss_mb="$rss_mb" -v fmax="$fmax" -v tc="$tc" -v vdep="$vdep" \
      -v newton="$newton" -v status="$status" -v note="$note" 'BEGIN {
        per_spmv  = (spmv > 0) ? sprintf("%.3f", tps / spmv) : "";
        per_solve = (solve > 0) ? sprintf("%.3f", tps / solve) : "";
        # The whole 400 us run at this dt: setup + factorization + steps.
        projected = sprintf("%.2f", setup + fact + output + ceil(400 / dt - 1e-9) * tps / 1e3);
        if (tc == "nan" || tc == "-nan") tc = "";
        if (vdep == "nan" || vdep == "-nan") vdep = "";
        printf "%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s\n",
          id, group, scheme, solver, precond, mesh, n_dofs, T, n_steps, dt,
          setup, fact, tps, spmv, solve, per_spmv, per_solve, loop, output,
          wall, elapsed, projected, rss_mb, fmax, tc, vdep, newton,
          status, (note == "") ? "" : "\"" note "\""
      }
      function ceil(x) { return (x == int(x)) ? x : int(x) + 1 }' >> "$csv"
  printf '%8.1f ms/step, wall %7.1f s, %7.0f MB%s\n' "$tps" "$elapsed" \
    "$(gnu_time_rss_mb "$dir/time.txt")" "${note:+  ($note)}"
}

skip_case() { # id group scheme solver precond mesh reason
  printf '%-34s %-11s skipped: %s\n' "$1" "$6" "${7%%:*}"
  echo "$1,$2,$3,$4,$5,$6,,,,,,,,,,,,,,,,,,,,,,,$(csv_quote "skipped: $7")" >> "$csv"
}

echo "fgimpact benchmark: $(date -Is), $(nproc) cores, $(uname -n), executable $exe_src"
echo "BLAS: $(readlink -f /usr/lib/x86_64-linux-gnu/libblas.so.3)"
echo "results: $out"

# --- 1. every solver path on every mesh.
for m in "${meshes[@]}"; do
  read -r label nx ny nz <<< "$m"
  for p in "${paths[@]}"; do
    read -r pid scheme solver precond <<< "$p"
    T=$(end_time "$pid" "$label")
    id=${pid}_${label}
    if [[ $T == skip:* ]]; then
      skip_case "$id" scaling "$scheme" "$solver" "$precond" "$label" "${T#skip:}"
    else
      run_case "$id" scaling "$scheme" "$solver" "$precond" "$nx" "$ny" "$nz" "$T"
    fi
  done
done

# --- 2. the issue's targets on the default scene (VTU off): the whole run
# of the default parameters (Linear solver/Type = auto), three times.
for r in 1 2 3; do
  run_case "default_auto_run$r" default implicit auto - 40 20 4 400
done

# --- 3. the issue's FEniCSx reference: homogeneous plate (E = 70 GPa,
# rho = 2707 kg/m^3 throughout), 40x20x4, dt = 1 us, 300 steps, 1 m/s.
homogeneous=("Material/Ceramic Young's modulus=70e9" "Material/Ceramic density=2707")
run_case homogeneous_cholmod homogeneous implicit cholmod - 40 20 4 300 "${homogeneous[@]}"
run_case homogeneous_explicit homogeneous explicit - - 40 20 4 300 "${homogeneous[@]}"

/usr/bin/python3 bench/make_table.py "$csv" > "$out/results.md"
echo "wrote $csv and $out/results.md"
