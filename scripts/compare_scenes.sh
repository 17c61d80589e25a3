#!/bin/bash
# The refactoring check of issue 39: run the 8 comparison scenes (default
# quarter, whole plate, hertz node, hertz midplane, explicit, resolved, J2,
# a 2-case study) and a static and a modal run with an executable into a directory, or compare two such
# directories file by file (history.csv, probes.csv, summary.txt, study.csv),
# leaving out the lines that hold timings and provenance.  A change that
# moves code keeps every other byte.
#
#   scripts/compare_scenes.sh run DIR [FGIMPACT]   (default build/fgimpact)
#   scripts/compare_scenes.sh diff DIR_A DIR_B     (exit 1 on a difference)
#
# The scenes are the default scene on a coarse 10x6x2 mesh, 200 us, so that
# the 10 runs take a few seconds in Release.
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/fgimpact_lib.sh

scenes=(quarter whole hertz_node hertz_midplane explicit resolved j2 study static
  modal)

run_scenes() {
  local dir=$1 exe=${2:-build/fgimpact}
  exe=$(realpath "$exe")
  mkdir -p "$dir"
  dir=$(realpath "$dir")
  local base=(Geometry/Subdivisions\ x=10 Geometry/Subdivisions\ y=6
    Geometry/Subdivisions\ z=2 "Time integration/Time step=2e-6"
    "Time integration/End time=200e-6" "Output/VTU interval=0"
    "Output/Print timing=false")
  local scene extra
  for scene in "${scenes[@]}"; do
    case $scene in
    quarter) extra=("Geometry/Symmetry=quarter") ;;
    whole) extra=("Geometry/Symmetry=none") ;;
    hertz_node) extra=("Geometry/Symmetry=none" "Contact/Model=hertz node") ;;
    hertz_midplane) extra=("Contact/Model=hertz midplane") ;;
    explicit) extra=("Time integration/Scheme=explicit"
      "Time integration/Time step=0") ;;
    resolved) extra=("Contact/Model=resolved sphere"
      "Geometry/Contact refinement levels=3") ;;
    j2) extra=("Contact/Model=resolved sphere" "Material/Plasticity=J2"
      "Geometry/Contact refinement levels=3") ;;
    study) extra=() ;;
    static) extra=("Problem type=static" "Static/Load=sphere"
      "Geometry/Contact refinement levels=2") ;;
    modal) extra=("Problem type=modal" "Geometry/Symmetry=none") ;;
    esac
    write_prm "$dir/$scene.prm" prm/default.prm "${base[@]}" "${extra[@]}" \
      "Output/Directory=$dir/$scene"
    local args=("$dir/$scene.prm")
    [[ $scene == study ]] && args+=(--study "Impactor/Initial velocity=1,2")
    if ! "$exe" "${args[@]}" >"$dir/$scene.stdout" 2>&1; then
      echo "compare_scenes: $scene failed (see $dir/$scene.stdout)" >&2
      return 1
    fi
  done
}

# The lines that differ between two runs of the same executable: the
# provenance header ("# date", "# command", ...) and the timings (keys and
# study.csv columns ending in _s or _ms).
strip_volatile() {
  if [[ $1 == *.csv ]]; then
    awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) keep[i] = ($i !~ /_m?s$/) }
      { line = ""; for (i = 1; i <= NF; ++i) if (keep[i]) line = line $i ",";
        print line }' "$1"
  elif [[ $1 == *.json ]]; then
    # The provenance object, and the timings.
    awk '/"provenance": \{/ { skip = 1 } !skip && !/"[a-z0-9_]+_m?s": / { print }
      skip && /\}/ { skip = 0 }' "$1"
  else
    grep -Ev '^(# |[a-z0-9_]+_m?s = )' "$1" || true
  fi
}

# The files a run reports its numbers in.
compared_files() {
  find "$1" -type f \( -name history.csv -o -name probes.csv \
    -o -name summary.txt -o -name summary.json -o -name study.csv \
    -o -name frequencies.csv -o -name contact_pressure.csv \
    -o -name load_curve.csv -o -name convergence.csv \) | sort
}

diff_scenes() {
  local a=$1 b=$2 status=0 f rel
  while IFS= read -r f; do
    rel=${f#"$a"/}
    if [[ ! -f $b/$rel ]]; then
      echo "missing in $b: $rel"
      status=1
    elif [[ $rel == *.csv && $rel != *study.csv ]]; then
      cmp -s "$f" "$b/$rel" || { echo "differs: $rel"; status=1; }
    elif ! diff -q <(strip_volatile "$f") <(strip_volatile "$b/$rel") \
      >/dev/null; then
      echo "differs: $rel"
      status=1
    fi
  done < <(compared_files "$a")
  [[ $status == 0 ]] && echo "compare_scenes: $(compared_files "$a" | wc -l)" \
    "files identical (timings and provenance aside)"
  return $status
}

case ${1:-} in
run) run_scenes "${@:2}" ;;
diff) diff_scenes "$2" "$3" ;;
*)
  sed -n '2,12p' "$0"
  exit 2
  ;;
esac
