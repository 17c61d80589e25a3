#!/usr/bin/env bash
# Checks scripts/render.py (run by scripts/test.sh after ctest): renders a
# small resolved-sphere run (a quarter, mirrored) and checks every picture
# it lists is a PNG of the asked size that is not blank: at least 5 % of
# its pixels differ from the corner's background colour and it has at
# least 50 colours (a colour map on a plate), read back with VTK's PNG
# reader in pvpython, independently of the renderer.  A bad command line
# must exit 2 with one line.  Skips cleanly (exit 0, a note) without
# pvpython (CI installs paraview, python3-paraview and xvfb).
# Usage: scripts/check_render.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
if ! command -v pvpython >/dev/null; then
  echo "check_render: skipped (no pvpython)"
  exit 0
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failed=0
check() { # what, command...
  local what=$1
  shift
  if "$@"; then echo "check_render: $what: yes"; else
    echo "check_render: $what: NO"
    failed=1
  fi
}
status=0
scripts/render.sh "$work/none" >/dev/null 2>"$work/err" || status=$?
check "a directory without solution.pvd refused (exit 2, one line)" \
  test "$status:$(wc -l <"$work/err")" = "2:1"

"$build/fgimpact" tests/run/default_small.prm -s "Output/Directory=$work/run" \
  -s "Geometry/Symmetry=quarter" -s "Contact/Model=resolved sphere" \
  -s "Time integration/End time=120e-6" -s "Output/Log interval=0" \
  -s "Output/VTU interval=10" >/dev/null
scripts/render.sh "$work/run" --frames 2 --size 640 400 >"$work/list"
check "render.py lists 7 files (4 pictures, the state, 2 frames)" \
  test "$(wc -l <"$work/list")" = 7
grep '\.png$' "$work/list" >"$work/pngs" || true
cat >"$work/blank.py" <<'PY'
import sys
import numpy
from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.util.numpy_support import vtk_to_numpy
bad = 0
for path in open(sys.argv[1]).read().split():
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    nx, ny, _ = image.GetDimensions()
    pixels = vtk_to_numpy(image.GetPointData().GetScalars())[:, :3]
    background = pixels[0]
    share = numpy.mean(numpy.any(pixels != background, axis=1))
    colours = len(numpy.unique(pixels, axis=0))
    ok = (nx, ny) == (640, 400) and share > 0.05 and colours >= 50
    print("%s: %dx%d, %.1f %% not background, %d colours: %s"
          % (path.split("/")[-1], nx, ny, 100 * share, colours,
             "yes" if ok else "NO"))
    bad += not ok
sys.exit(1 if bad else 0)
PY
if xvfb-run -a pvpython "$work/blank.py" "$work/pngs" >"$work/report" 2>&1; then
  blank_ok=1
else
  blank_ok=0
fi
sed 's/^/check_render:   /' "$work/report" | grep -v "^check_render:   $" || true
check "every picture is not blank" test "$blank_ok" = 1
exit $failed
