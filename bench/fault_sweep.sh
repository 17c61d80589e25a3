#!/usr/bin/env bash
# The fault sweep of issue 40, re-run: each finding's reproduction (inputs a
# careful user gives, faults a hostile machine brings) with a time limit,
# classified as
#   ok         the run ended as documented (a one-line refusal, a failed or
#              interrupted summary, or identical files);
#   HANG       it did not end within its limit (or ignored a signal);
#   LOSS       a file it must not touch changed, or a resumed run's files
#              differ from an uninterrupted run's;
#   NOSUMMARY  it died with no summary.txt saying how it ended;
#   GARBAGE    it ended "completed" (or exit 0) where it should not have, or
#              printed something misleading.
# The base scene is the issue's: the default plate at 8 x 4 x 2, dt 2 us,
# End time 200 us, no VTU.  Cases needing a mount (a full disk) use a
# tmpfs where the machine allows one and are skipped, with a line, where not.
# Usage: bench/fault_sweep.sh [CASE-REGEX]   (about 6 minutes, 2 cores)
#        FGIMPACT=path/to/fgimpact to use another executable.
set -uo pipefail
cd "$(dirname "$0")/.."
. scripts/fgimpact_lib.sh
exe=$(realpath "${FGIMPACT:-build/fgimpact}")
filter=${1:-.}
root=$(mktemp -d)
trap 'umount "$root/small" 2>/dev/null; rm -rf "$root"' EXIT
allow_local_mpirun
cd "$root"
declare -A count=([ok]=0 [HANG]=0 [LOSS]=0 [NOSUMMARY]=0 [GARBAGE]=0 [skipped]=0)

cat >base.prm <<EOF
include $OLDPWD/prm/default.prm
subsection Geometry
  set Subdivisions x = 8
  set Subdivisions y = 4
  set Subdivisions z = 2
end
subsection Time integration
  set Time step = 2e-6
  set End time  = 200e-6
end
subsection Output
  set Directory    = out
  set VTU interval = 0
  set Snapshot at peak force = false
  set Report = false
end
EOF

# run LIMIT CMD...: run CMD (a shell string) with a time limit (s); sets rc,
# wall (s) and lines (stderr's line count); rc 124/137 is a hang.
run() {
  local limit=$1
  shift
  local start=$(date +%s.%N)
  timeout -k 5 "$limit" bash -c "$*" >stdout.txt 2>stderr.txt
  rc=$?
  wall=$(echo "$(date +%s.%N) - $start" | bc)
  lines=$(wc -l <stderr.txt)
}
status_of() { summary_value "$1" status 2>/dev/null || echo none; }
hung() { [ "$rc" = 124 ] || [ "$rc" = 137 ]; }
# verdict NAME CLASS DETAIL
verdict() {
  count[$2]=$((count[$2] + 1))
  printf '%-9s %-58s %s\n' "$2" "$1" "$3"
}
wanted() { [[ "$1" =~ $filter ]]; }
# refusal NAME LIMIT WORD CMD: a one-line refusal naming WORD, exit 1 or 2.
refusal() {
  local name=$1 limit=$2 word=$3
  shift 3
  wanted "$name" || return 0
  rm -rf out
  run "$limit" "$@"
  if hung; then
    verdict "$name" HANG "no end within $limit s"
  elif [ "$rc" = 0 ]; then
    verdict "$name" GARBAGE "exit 0, not refused"
  elif [ "$lines" -ne 1 ] || ! grep -qF -- "$word" stderr.txt; then
    verdict "$name" GARBAGE "exit $rc, $lines lines, '$word' named: no"
  else
    verdict "$name" ok "exit $rc in $(printf %.1f "$wall") s, one line naming '$word'"
  fi
}
# ended NAME LIMIT STATUS CMD: the run ends within LIMIT with out/summary.txt
# status STATUS.
ended() {
  local name=$1 limit=$2 want=$3
  shift 3
  wanted "$name" || return 0
  rm -rf out
  run "$limit" "$@"
  local status=$(status_of out)
  if hung; then
    verdict "$name" HANG "no end within $limit s"
  elif [ "$status" = none ] && [ "$rc" != 1 ]; then
    verdict "$name" NOSUMMARY "exit $rc, no summary.txt"
  elif [ "$rc" = 1 ] && [ "$lines" = 1 ]; then
    verdict "$name" ok "refused in one line, exit 1, $(printf %.1f "$wall") s"
  elif [ "$status" != "$want" ]; then
    verdict "$name" GARBAGE "status $status, expected $want (exit $rc)"
  else
    verdict "$name" ok "exit $rc in $(printf %.1f "$wall") s, status $status"
  fi
}
# signalled NAME SIGNAL AFTER LIMIT STATUS CMD: CMD in the background, the
# signal after AFTER s (to the process group), then it must end within LIMIT
# s more with status STATUS.
signalled() {
  local name=$1 sig=$2 after=$3 limit=$4 want=$5
  shift 5
  wanted "$name" || return 0
  rm -rf out
  setsid bash -c "$*" >stdout.txt 2>stderr.txt &
  local pid=$!
  sleep "$after"
  kill -s "$sig" -- -"$pid" 2>/dev/null
  local start=$(date +%s.%N) waited=0
  while kill -0 "$pid" 2>/dev/null && [ "$waited" -lt "$limit" ]; do
    sleep 1
    waited=$((waited + 1))
  done
  if kill -0 "$pid" 2>/dev/null; then
    kill -KILL -- -"$pid" 2>/dev/null
    wait "$pid" 2>/dev/null
    verdict "$name" HANG "SIG$sig at $after s: still running $limit s later"
    return
  fi
  wait "$pid"
  rc=$?
  local status=$(status_of out)
  if [ "$status" = none ]; then
    verdict "$name" NOSUMMARY "SIG$sig at $after s: exit $rc, no summary.txt"
  elif [ "$status" != "$want" ]; then
    verdict "$name" GARBAGE "SIG$sig at $after s: status $status, expected $want"
  else
    verdict "$name" ok "SIG$sig at $after s: exit $rc within $waited s, status $status"
  fi
}
# wait_checkpoint DIR PID: until DIR/checkpoint holds a file (60 s at
# most, or until PID ends).
wait_checkpoint() {
  local tries=0
  while [ "$(ls "$1/checkpoint" 2>/dev/null | wc -l)" -lt 1 ] &&
    kill -0 "$2" 2>/dev/null && [ "$tries" -lt 600 ]; do
    sleep 0.1
    tries=$((tries + 1))
  done
}
# killed_after_checkpoint SECONDS CMD: CMD (writing into out/) killed with
# SIGKILL, its launcher and ranks, SECONDS after its first checkpoint.
killed_after_checkpoint() {
  rm -rf out
  setsid bash -c "$2" >/dev/null 2>&1 &
  local pid=$!
  wait_checkpoint out "$pid"
  sleep "$1"
  killed=no
  kill -0 "$pid" 2>/dev/null && killed=yes
  kill -KILL -- -"$pid" 2>/dev/null
  wait "$pid" 2>/dev/null
}
# same NAME A B FILES...: FILES identical in directories A and B.
same() {
  local name=$1 a=$2 b=$3 detail=$4
  shift 4
  local f differ=""
  # deal.II stamps each VTU with the time of day it wrote it.
  for f in "$@"; do
    cmp -s <(grep -av "generated by the deal.II library" "$a/$f") \
      <(grep -av "generated by the deal.II library" "$b/$f") || differ="$differ $f"
  done
  if [ -n "$differ" ]; then
    verdict "$name" LOSS "$detail; differ:$differ"
  else
    verdict "$name" ok "$detail; identical: $*"
  fi
}

x="$exe base.prm"
echo "fault sweep of $exe, $(date -u +%F)"

# --- Hangs -------------------------------------------------------------------
ended "memory limit 700 MB, 135 DoFs" 60 completed "ulimit -v 700000; $x"
ended "memory limit 650 MB, 40x20x4" 60 completed \
  "ulimit -v 650000; $exe $OLDPWD/prm/default.prm -s Output/Directory=out -s 'Output/VTU interval=0' -s Output/Report=false"
ended "memory limit 700 MB, J2 at level 7" 120 completed \
  "ulimit -v 700000; $x -s 'Contact/Model=resolved sphere' -s Material/Plasticity=J2 -s 'Geometry/Contact refinement levels=7' -s 'Time integration/End time=20e-6'"
refusal "study whose cases cannot fit (400x200x40, whole)" 30 "study case 0" \
  "$x -s Geometry/Symmetry=none -s 'Geometry/Subdivisions x=400' -s 'Geometry/Subdivisions y=200' -s 'Geometry/Subdivisions z=40' --study 'Impactor/Initial velocity=1,2,3'"
refusal "converged, ball in contact at End time" 60 "End time" \
  "$x -s Accuracy=converged -s 'Contact/Model=resolved sphere' -s 'Time integration/End time=40e-6'"
refusal "converged, tolerance 1e-6" 60 "cannot be reached" \
  "$x -s Accuracy=converged -s 'Accuracy tolerance=1e-6' -s 'Contact/Model=resolved sphere'"
signalled "SIGTERM 20 s into a 400x200x40 quarter's set-up" TERM 20 10 interrupted \
  "$x -s 'Geometry/Subdivisions x=400' -s 'Geometry/Subdivisions y=200' -s 'Geometry/Subdivisions z=40'"
signalled "modal, 500 modes, SIGTERM at 10 s" TERM 10 10 interrupted \
  "$exe $OLDPWD/prm/default.prm -s 'Problem type=modal' -s 'Modal/Number of modes=500' -s Geometry/Symmetry=none -s Output/Directory=out -s Output/Report=false"
# It computes (minutes of subspace iteration), so the test is that a signal
# still stops it.
signalled "modal, 500 modes, memory limit 3 GB, 80x40x8, SIGTERM at 20 s" TERM 20 10 interrupted \
  "ulimit -v 3000000; $exe $OLDPWD/prm/default.prm -s 'Problem type=modal' -s 'Modal/Number of modes=500' -s Geometry/Symmetry=none -s 'Geometry/Subdivisions x=80' -s 'Geometry/Subdivisions y=40' -s 'Geometry/Subdivisions z=8' -s Output/Directory=out -s Output/Report=false"

# 2-rank J2 resume after SIGKILL, and after a completed run.
if wanted "2-rank J2 resume"; then
  j2="-s 'Contact/Model=resolved sphere' -s Material/Plasticity=J2 -s 'Geometry/Contact refinement levels=4' -s 'Time integration/Time step=0.5e-6' -s 'Output/Checkpoint interval=40' -s 'Linear solver/Type=klu' -s Output/Directory=DIR"
  # KLU: the distributed MUMPS is not bit-reproducible from run to run.
  run 120 "mpirun -n 2 $x ${j2//DIR/ref}"
  killed_after_checkpoint 0.2 "mpirun -n 2 $x ${j2//DIR/out}"
  run 120 "mpirun -n 2 $exe --resume out"
  if hung; then
    verdict "2-rank J2 resume after SIGKILL" HANG "no end within 120 s"
  else
    same "2-rank J2 resume after SIGKILL" ref out "killed mid-run $killed, exit $rc" history.csv probes.csv
  fi
  run 120 "mpirun -n 2 $exe --resume ref"
  if hung; then
    verdict "2-rank J2 resume of a completed run" HANG "no end within 120 s"
  else
    verdict "2-rank J2 resume of a completed run" ok "exit $rc in $(printf %.1f "$wall") s, $lines line(s)"
  fi
fi

# --- Lost or changed data -----------------------------------------------------
if wanted "refused --resume"; then
  rm -rf out
  run 60 "$x -s 'Output/Checkpoint interval=20' -s 'Time integration/End time=auto'"
  md5sum out/parameters.prm out/summary.txt >before.md5
  run 60 "$exe --resume out -s 'Time integration/Maximum end time=1e-12'"
  if md5sum --quiet -c before.md5 >/dev/null 2>&1 && [ "$rc" != 0 ]; then
    verdict "refused --resume (Maximum end time 1e-12)" ok "exit $rc, parameters.prm and summary.txt unchanged"
  else
    verdict "refused --resume (Maximum end time 1e-12)" LOSS "exit $rc, files changed"
  fi
  run 60 "$exe --resume out -s 'Time integration/End time=100e-6'"
  if md5sum --quiet -c before.md5 >/dev/null 2>&1 && [ "$rc" != 0 ]; then
    verdict "refused --resume (End time before the checkpoint)" ok "exit $rc, parameters.prm and summary.txt unchanged"
  else
    verdict "refused --resume (End time before the checkpoint)" LOSS "exit $rc, files changed"
  fi
fi
if wanted "lock file a symbolic link"; then
  rm -rf out && mkdir out && echo "my notes" >notes.txt
  ln -s "$root/notes.txt" out/.fgimpact.lock
  run 60 "$x -s Output/Overwrite=true"
  if [ "$(cat notes.txt)" = "my notes" ]; then
    verdict "lock file a symbolic link to a user's file" ok "exit $rc, the user's file unchanged"
  else
    verdict "lock file a symbolic link to a user's file" LOSS "the user's file was written"
  fi
fi
if wanted "peak fields after SIGKILL"; then
  j2="-s 'Contact/Model=resolved sphere' -s Material/Plasticity=J2 -s 'Geometry/Contact refinement levels=5' -s 'Time integration/Time step=0.25e-6' -s 'Output/Checkpoint interval=80' -s 'Output/VTU interval=1000' -s Output/Directory=DIR"
  run 120 "$x ${j2//DIR/ref}"
  killed_after_checkpoint 0 "$x ${j2//DIR/out}"
  run 120 "$exe --resume out"
  peak=$(cd ref && ls vtu | grep peak_fields)
  same "peak fields after SIGKILL and --resume (J2)" ref out "killed mid-run $killed, exit $rc" \
    $(for f in $peak; do echo "vtu/$f"; done) history.csv
fi
if wanted "Overwrite keeps a user's file"; then
  # An earlier run (VTU every 50 steps, its manifest), then a user's file
  # with a name of ours that run did not write.  (A directory without any
  # manifest is an earlier version's output: its exact names go, as
  # doc/robustness.md says.)
  rm -rf out
  run 60 "$x -s 'Output/VTU interval=50'"
  echo "mine" >mine.vtu && cp mine.vtu out/vtu/solution_00020.0.vtu
  run 60 "$x -s 'Output/VTU interval=0' -s Output/Overwrite=true"
  if cmp -s mine.vtu out/vtu/solution_00020.0.vtu; then
    verdict "Overwrite keeps a user's file named like ours" ok "exit $rc, kept"
  else
    verdict "Overwrite keeps a user's file named like ours" LOSS "removed"
  fi
fi
if wanted "full disk"; then
  mkdir -p small
  if mount -t tmpfs -o size=1m tmpfs small 2>/dev/null; then
    ended "full disk (1 MB tmpfs), VTU every 10 steps" 60 failed \
      "$x -s 'Output/VTU interval=10' -s Output/Directory=small/out; code=\$?; cp -r small/out out 2>/dev/null; exit \$code"
    umount small
  else
    count[skipped]=$((count[skipped] + 1))
    echo "skipped   full disk: no tmpfs mount here (signal_stop and mpi_output_failure inject it)"
  fi
fi

# --- Deaths without a summary -------------------------------------------------
ended "ulimit -f 60 kB, VTU every step" 60 failed \
  "ulimit -f 60; $x -s 'Output/VTU interval=1' -s 'Output/VTU compression=none'"
if wanted "convolution study"; then
  # Stopped while it prepares: no case has started, so there is no case
  # summary; the study's log.txt and the one line say how it ended.
  rm -rf out
  printf 'include %s\nsubsection Time integration\n set End time = 0.002\nend\nsubsection Study\n set Entries = Impactor/Initial velocity = 1, 2, 3, 4, 5, 6, 7, 8, 9, 10\nend\nsubsection Output\n set Directory = out\n set VTU interval = 0\n set Report = false\nend\n' "$OLDPWD/prm/default.prm" >convolution.prm
  "$exe" convolution.prm >stdout.txt 2>stderr.txt &
  pid=$!
  for ((i = 0; i < 300; ++i)); do [ -e out/log.txt ] && break; sleep 0.01; done
  sleep 1
  kill -TERM "$pid"
  wait "$pid"
  rc=$?
  if [ "$rc" = 143 ] && [ "$(wc -l <stderr.txt)" = 1 ] &&
    tail -n 1 out/log.txt | grep -q "interrupted by SIGTERM while the convolution study"; then
    verdict "SIGTERM during a convolution study's unit responses" ok "exit 143, one line, the same line ends the study's log.txt"
  else
    verdict "SIGTERM during a convolution study's unit responses" NOSUMMARY "exit $rc, no record in out/log.txt"
  fi
fi
signalled "SIGTERM during the factorization of 80x40x8" TERM 2 30 interrupted \
  "$exe $OLDPWD/prm/default.prm -s Geometry/Symmetry=none -s 'Geometry/Subdivisions x=80' -s 'Geometry/Subdivisions y=40' -s 'Geometry/Subdivisions z=8' -s Output/Directory=out -s 'Output/VTU interval=0' -s Output/Report=false"
signalled "SIGTERM in the time loop of 80x40x8" TERM 8 30 interrupted \
  "$exe $OLDPWD/prm/default.prm -s Geometry/Symmetry=none -s 'Geometry/Subdivisions x=80' -s 'Geometry/Subdivisions y=40' -s 'Geometry/Subdivisions z=8' -s Output/Directory=out -s 'Output/VTU interval=0' -s Output/Report=false"
signalled "2 ranks, SIGUSR1 to mpirun during set-up" USR1 2 30 interrupted \
  "mpirun -n 2 $exe $OLDPWD/prm/default.prm -s 'Geometry/Subdivisions x=80' -s 'Geometry/Subdivisions y=40' -s 'Geometry/Subdivisions z=8' -s Output/Directory=out -s 'Output/VTU interval=0' -s Output/Report=false"

# --- Misleading ---------------------------------------------------------------
refusal "snapshot times closer than 1 ns" 30 "Snapshot times" \
  "$x -s 'Output/Snapshot times=50e-6, 50.0001e-6'"
if wanted "snapshot time after an automatic end"; then
  rm -rf out
  run 60 "$x -s 'Time integration/End time=auto' -s 'Output/Snapshot times=900e-6'"
  if grep -q "900" <(summary_value out warnings 2>/dev/null); then
    verdict "snapshot time after an automatic end" ok "exit $rc, in summary.txt's warnings"
  else
    verdict "snapshot time after an automatic end" GARBAGE "not in summary.txt's warnings"
  fi
fi
if wanted "converged"; then
  rm -rf conv
  run 120 "$x -s Accuracy=converged -s 'Contact/Model=resolved sphere' -s 'Accuracy tolerance=0.3' -s Output/Directory=conv"
  level=$(ls -d conv/convergence/*/ 2>/dev/null | head -1)
  refusal "--resume of a converged run's level folder" 30 "parameters.prm" "$exe --resume $level"
  # A level folder of ours the second run will not write (level_99: a
  # finer level of the first run), and a user's folder beside them.
  mkdir -p conv/convergence/level_99 conv/convergence/my_notes
  cp -r "$level"/. conv/convergence/level_99/ 2>/dev/null
  touch conv/convergence/my_notes/x
  run 120 "$x -s Accuracy=converged -s 'Contact/Model=resolved sphere' -s 'Accuracy tolerance=0.3' -s Output/Directory=conv -s Output/Overwrite=true"
  if [ -e conv/convergence/level_99 ]; then
    verdict "a second converged run into the same directory" LOSS "exit $rc, the first run's level_99 left beside the new levels"
  elif [ ! -e conv/convergence/my_notes/x ]; then
    verdict "a second converged run into the same directory" LOSS "exit $rc, a user's folder removed"
  else
    verdict "a second converged run into the same directory" ok "exit $rc, the first run's levels gone, a user's folder kept"
  fi
fi
if wanted "nested lock"; then
  rm -rf out
  setsid bash -c "$x -s 'Geometry/Subdivisions x=40' -s 'Geometry/Subdivisions y=20' -s 'Geometry/Subdivisions z=8' --study 'Impactor/Initial velocity=1,2,3,4'" >/dev/null 2>&1 &
  pid=$!
  for ((i = 0; i < 300; ++i)); do [ -e out/.fgimpact.lock ] && break; sleep 0.1; done
  run 30 "$x -s Output/Directory=out/case_001"
  kill -TERM -- -"$pid" 2>/dev/null
  wait "$pid" 2>/dev/null
  if [ "$rc" = 1 ] && [ "$lines" = 1 ]; then
    verdict "nested lock: a run into a running study's case" ok "refused in one line"
  else
    verdict "nested lock: a run into a running study's case" GARBAGE "exit $rc, $lines lines"
  fi
fi
if wanted "Radius 1e-6"; then
  rm -rf out
  run 60 "$x -s 'Impactor/Radius=1e-6' -s 'Impactor/Initial velocity=1'"
  if grep -q "departure_velocity_m_s = 2.99" out/summary.txt 2>/dev/null; then
    verdict "Radius 1e-6: advice and failed summary" GARBAGE "departure velocity 2.99 for V0 = 1"
  elif grep -q "^e Time" stderr.txt; then
    verdict "Radius 1e-6: advice and failed summary" GARBAGE "advice cut mid-word"
  else
    verdict "Radius 1e-6: advice and failed summary" ok "exit $rc, $lines line(s), status $(status_of out)"
  fi
fi
if wanted "NUL"; then
  rm -rf out
  head -c 5000000 /dev/zero | tr '\0' 'x' >big.txt
  { cat base.prm; printf 'subsection Output\n set Directory = '; cat big.txt; printf '\nend\n'; } >big.prm
  run 30 "$exe big.prm"
  len=$(wc -c <stderr.txt)
  if [ "$lines" = 1 ] && [ "$len" -lt 1000 ]; then
    verdict "a 5 MB value: one short line" ok "exit $rc, $len bytes"
  else
    verdict "a 5 MB value: one short line" GARBAGE "$lines lines, $len bytes"
  fi
  printf 'subsection Output\n set Directory = o\001ut\000x\nend\n' >nul.prm
  run 30 "$exe nul.prm"
  if [ "$lines" = 1 ] && ! grep -qaP '[\x00-\x08]' stderr.txt; then
    verdict "control bytes in a value: escaped" ok "exit $rc, one line"
  else
    verdict "control bytes in a value: escaped" GARBAGE "$lines lines or raw control bytes"
  fi
fi
if wanted "probes.csv removed"; then
  rm -rf out
  run 60 "$x -s 'Output/Checkpoint interval=20'"
  cp out/summary.txt summary.before
  rm -f out/probes.csv
  run 60 "$exe --resume out"
  if cmp -s summary.before out/summary.txt; then
    verdict "probes.csv removed, --resume of a completed run" ok "exit $rc, summary.txt kept"
  else
    verdict "probes.csv removed, --resume of a completed run" LOSS "summary.txt replaced"
  fi
fi
refusal "newline in Output/Directory" 30 "Directory" \
  "$x -s \$'Output/Directory=a\\nb'"
refusal "a study varying Output/Directory" 30 "Output/Directory" \
  "$x --study 'Output/Directory=a,b'"
refusal "--study-case 0 without a study" 30 "study" "$x --study-case 0"
if wanted "End time 15 us with dt 10 us"; then
  rm -rf out
  run 30 "$x -s 'Time integration/Time step=10e-6' -s 'Time integration/End time=15e-6'"
  if [ "$rc" != 0 ] || grep -q "not a whole number of time steps" stdout.txt; then
    verdict "End time 15 us with dt 10 us" ok "exit $rc: refused or said"
  else
    verdict "End time 15 us with dt 10 us" GARBAGE "ran to another time silently"
  fi
fi

echo
total=0
for k in ok HANG LOSS NOSUMMARY GARBAGE; do total=$((total + count[$k])); done
echo "$total cases: ${count[ok]} ok, ${count[HANG]} hangs, ${count[LOSS]} data loss," \
  "${count[NOSUMMARY]} deaths without summary, ${count[GARBAGE]} silent garbage;" \
  "${count[skipped]} skipped"
