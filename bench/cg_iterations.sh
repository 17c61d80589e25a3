#!/usr/bin/env bash
# CG iteration counts of the implicit path (the program does not print
# them): counts the calls of dealii::SolverControl::check under gdb, once
# per CG iteration plus once per solve.  Two runs per case, 1 step and
# N steps: the difference gives the iterations of a warm-started time step
# (start = the previous displacement), the 1-step run the iterations of the
# 4 solves from a zero start made during initialization (unit force, and
# the 3 reference solves behind solve_ms, Output/Instrumentation = true).
# The program now reports the iterations itself (linear_solver_iterations
# in summary.txt); this script stays as an independent count.
#
#   bench/cg_iterations.sh [--out DIR] [nx:ny:nz:preconditioner:N ...]
#
# Timings under gdb are meaningless; only the counts are used.
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/fgimpact_lib.sh

out=output/bench/cg_iterations
if [ "${1:-}" = --out ]; then out=$2; shift 2; fi
cases=("$@")
[ ${#cases[@]} -gt 0 ] || cases=(40:20:4:jacobi:100 40:20:4:ssor:50 40:20:4:amg:20
  80:40:8:jacobi:20 80:40:8:amg:10 120:60:8:jacobi:10 120:60:8:amg:5
  160:80:16:jacobi:5)

command -v gdb > /dev/null || { SUDO=""; [ "$(id -u)" -eq 0 ] || SUDO="sudo"; $SUDO apt-get install -y gdb; }
mkdir -p "$out"
out=$(cd "$out" && pwd)
exe=$(copy_executable "$out")
cat > "$out/count.gdb" <<'GDB'
set breakpoint pending on
set pagination off
break dealii::SolverControl::check
ignore 1 2000000000
run
info breakpoints
GDB

hits() { # prm
  gdb -batch -x "$out/count.gdb" --args "$exe" "$1" 2>&1 |
    sed -n 's/.*breakpoint already hit \([0-9]*\) time.*/\1/p'
}

echo "| mesh | preconditioner | CG iterations per time step (warm start) | CG iterations from a zero start | steps counted |"
echo "|---|---|---|---|---|"
for c in "${cases[@]}"; do
  IFS=: read -r nx ny nz pc n <<< "$c"
  for steps in 1 "$n"; do
    write_prm "$out/${nx}x${ny}x${nz}_${pc}_$steps.prm" prm/default.prm \
      "Geometry/Symmetry=none" \
      "Geometry/Subdivisions x=$nx" "Geometry/Subdivisions y=$ny" \
      "Geometry/Subdivisions z=$nz" "Time integration/End time=${steps}e-6" \
      "Linear solver/Type=cg" "Linear solver/Preconditioner=$pc" \
      "Output/Directory=$out/run_${nx}x${ny}x${nz}_${pc}_$steps" \
      "Output/Instrumentation=true" "Output/VTU interval=0" "Output/Log interval=0"
  done
  h1=$(hits "$out/${nx}x${ny}x${nz}_${pc}_1.prm")
  hn=$(hits "$out/${nx}x${ny}x${nz}_${pc}_$n.prm")
  awk -v h1="$h1" -v hn="$hn" -v n="$n" -v mesh="${nx}x${ny}x${nz}" -v pc="$pc" 'BEGIN {
    w = (hn - h1) / (n - 1) - 1;     # hits per step = iterations + 1
    z = (h1 - (w + 1)) / 4 - 1;      # 4 zero-start solves in the 1-step run
    printf "| %s | %s | %.1f | %.1f | %d |\n", mesh, pc, w, z, n - 1 }'
done
