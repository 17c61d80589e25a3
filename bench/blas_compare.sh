#!/usr/bin/env bash
# CHOLMOD factorization and solve with OpenBLAS (serial) against the
# reference BLAS/LAPACK (Debian's libblas3/liblapack3), one run each, on
# the default mesh (400 us) and on 80x40x8 (20 us: the factorization and the
# solve are what is compared).
#
#   bench/blas_compare.sh [--alternatives] [--out DIR]
#
# Default method: the reference libraries are put in front of the dynamic
# loader's search path for the run only (LD_LIBRARY_PATH=.../blas:.../lapack;
# ldd verifies which libblas.so.3 is loaded), nothing system-wide changes.
# --alternatives: switch the system-wide alternatives instead
# (update-alternatives --set libblas.so.3-x86_64-linux-gnu .../blas/...,
# the same for liblapack), as root; they are ALWAYS set back to --auto
# (OpenBLAS) on exit, on error and on Ctrl-C.
#
# Results: DIR/blas.csv (default DIR = output/bench/blas).  The
# factorization_s column is the program's whole stepper initialization:
# K + a0 M, CHOLMOD analyze + factorize, the unit-force solve and the
# in-run reference measurements (20 SpMV, 3 solves); factor_only_s subtracts
# 4 solves and 20 SpMVs.
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/fgimpact_lib.sh

method=ldpath
out=output/bench/blas
while [ $# -gt 0 ]; do
  case "$1" in
    --alternatives) method=alternatives ;;
    --out) out=$2; shift ;;
    -h|--help) sed -n '2,22p' "$0"; exit 0 ;;
    *) echo "unknown option $1" >&2; exit 1 ;;
  esac
  shift
done

need_gnu_time

lib=/usr/lib/x86_64-linux-gnu
ref_blas=$lib/blas/libblas.so.3
ref_lapack=$lib/lapack/liblapack.so.3
[ -e "$ref_blas" ] && [ -e "$ref_lapack" ] || { echo "reference BLAS/LAPACK missing (apt-get install libblas3 liblapack3)" >&2; exit 1; }

mkdir -p "$out"
out=$(cd "$out" && pwd)
exe=$(copy_executable "$out")

restore() {
  if [ "$method" = alternatives ]; then
    update-alternatives --auto libblas.so.3-x86_64-linux-gnu || true
    update-alternatives --auto liblapack.so.3-x86_64-linux-gnu || true
    echo "restored: libblas.so.3 -> $(readlink -f $lib/libblas.so.3)"
  fi
}
if [ "$method" = alternatives ]; then
  trap restore EXIT
  trap 'exit 130' INT TERM HUP
fi

set_blas() { # openblas | reference
  if [ "$method" = alternatives ]; then
    if [ "$1" = reference ]; then
      update-alternatives --set libblas.so.3-x86_64-linux-gnu "$ref_blas" > /dev/null
      update-alternatives --set liblapack.so.3-x86_64-linux-gnu "$ref_lapack" > /dev/null
    else
      update-alternatives --auto libblas.so.3-x86_64-linux-gnu > /dev/null
      update-alternatives --auto liblapack.so.3-x86_64-linux-gnu > /dev/null
    fi
    ENVV=()
  else
    if [ "$1" = reference ]; then
      ENVV=(env "LD_LIBRARY_PATH=$lib/blas:$lib/lapack${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}")
    else
      ENVV=()
    fi
  fi
}

csv=$out/blas.csv
[ -s "$csv" ] || echo "method,blas,mesh,n_dofs,end_time_us,libblas_loaded,setup_s,factorization_s,factor_only_s,solve_ms,spmv_ms,time_per_step_ms,step_per_solve,wall_time_s,peak_rss_MB" > "$csv"

for case in "40 20 4 400" "80 40 8 20"; do
  read -r nx ny nz T <<< "$case"
  for blas in openblas reference; do
    set_blas $blas
    mesh=${nx}x${ny}x${nz}
    dir=$out/${method}_${blas}_${mesh}
    mkdir -p "$dir"
    write_prm "$dir/run.prm" prm/default.prm "Geometry/Symmetry=none" \
      "Geometry/Subdivisions x=$nx" "Geometry/Subdivisions y=$ny" \
      "Geometry/Subdivisions z=$nz" "Time integration/End time=${T}e-6" \
      "Linear solver/Type=cholmod" \
      "Output/Instrumentation=true" "Output/Directory=$dir" "Output/VTU interval=0" "Output/Log interval=0"
    loaded=$("${ENVV[@]}" ldd "$exe" | awk '$1 == "libblas.so.3" {print $3}')
    loaded=$(readlink -f "$loaded")
    "${ENVV[@]}" /usr/bin/time -v -o "$dir/time.txt" "$exe" "$dir/run.prm" > "$dir/run.log" 2>&1
    rss=$(gnu_time_rss_mb "$dir/time.txt" %.1f)
    line=$(awk -v m="$method" -v b="$blas" -v mesh="$mesh" -v T="$T" -v lib="$loaded" \
      -v n="$(summary_value "$dir" n_dofs)" \
      -v setup="$(summary_value "$dir" setup_s)" \
      -v fact="$(summary_value "$dir" factorization_s)" \
      -v solve="$(summary_value "$dir" solve_ms)" \
      -v spmv="$(summary_value "$dir" spmv_ms)" \
      -v tps="$(summary_value "$dir" time_per_step_ms)" \
      -v wall="$(summary_value "$dir" wall_time_s)" -v rss="$rss" 'BEGIN {
        printf "%s,%s,%s,%s,%s,%s,%s,%s,%.3f,%s,%s,%s,%.3f,%s,%s\n", m, b, mesh, n, T, lib,
          setup, fact, fact - (4 * solve + 20 * spmv) / 1e3, solve, spmv, tps,
          tps / solve, wall, rss }')
    echo "$line" | tee -a "$csv"
  done
done
