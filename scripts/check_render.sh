#!/usr/bin/env bash
# Checks scripts/render.py (run by scripts/test.sh after ctest): renders a
# small resolved-sphere run (a quarter, mirrored) and checks every picture
# it lists is a PNG of the asked size that is not blank: at least 5 % of
# its pixels differ from the corner's background colour and it has at
# least 50 colours (a colour map on a plate), read back with VTK's PNG
# reader in pvpython, independently of the renderer; and that each
# picture's colour range (colours.csv) follows the rule from the VTU data.
# A bad command line
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
check "render.py lists 10 files (6 pictures, the state, 2 frames, the movie)" \
  test "$(wc -l <"$work/list")" = 10
# The movie, read back: its AVI header's frame count (avih, dwTotalFrames)
# and size against the frames listed, which are distinct pictures.
cat >"$work/movie.py" <<'PY'
import hashlib, struct, sys
listed = open(sys.argv[1]).read().split()
frames = [p for p in listed if "/animation/frame_" in p]
movie = [p for p in listed if p.endswith(".avi")]
data = open(movie[0], "rb").read() if movie else b""
at = data.find(b"avih")
total, width, height = (struct.unpack("<I", data[at + 24:at + 28])[0],
                        *struct.unpack("<II", data[at + 40:at + 48])) if at >= 0 else (0, 0, 0)
distinct = len({hashlib.md5(open(p, "rb").read()).hexdigest() for p in frames})
print("animation.avi: %d frames of %dx%d; %d frame files, %d distinct"
      % (total, width, height, len(frames), distinct))
sys.exit(0 if total == len(frames) == distinct and total > 0
         and (width, height) == (640, 400) else 1)
PY
movie_ok=0
python3 "$work/movie.py" "$work/list" >"$work/movie" && movie_ok=1
sed 's/^/check_render:   /' "$work/movie"
check "the movie holds every frame, once, at the frames' size" test "$movie_ok" = 1
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

# The colour rule, read back: each picture's range in colours.csv against
# the field's range over every snapshot, read here from the VTU files with
# VTK's own reader (not ParaView's pipeline).  sigma_*: diverging, -M to M
# with M the largest magnitude; every other field: sequential, 0 to the
# largest value; the animation's range equals the still's of its field.
cat >"$work/colours.py" <<'PY'
import csv, math, os, sys
import xml.etree.ElementTree as ET
import numpy
from vtkmodules.vtkIOXML import vtkXMLPUnstructuredGridReader, vtkXMLUnstructuredGridReader
from vtkmodules.util.numpy_support import vtk_to_numpy
run, pictures = sys.argv[1], sys.argv[2]

def run_range(pvd, field):
    low, high = math.inf, -math.inf
    for d in ET.parse(os.path.join(run, pvd)).getroot().iter("DataSet"):
        path = os.path.join(run, d.get("file"))
        reader = (vtkXMLPUnstructuredGridReader() if path.endswith(".pvtu")
                  else vtkXMLUnstructuredGridReader())
        reader.SetFileName(path)
        reader.Update()
        values = vtk_to_numpy(reader.GetOutput().GetPointData().GetArray(field))
        if values.ndim > 1:
            values = numpy.linalg.norm(values, axis=1)
        low, high = min(low, values.min()), max(high, values.max())
    return low, high

bad = 0
ranges = {}
for row in csv.DictReader(open(os.path.join(pictures, "colours.csv"))):
    field = row["field"]
    pvd = "contact.pvd" if field == "contact_pressure_MPa" else "solution.pvd"
    low, high = run_range(pvd, field)
    lo, hi = float(row["low"]), float(row["high"])
    close = lambda a, b: abs(a - b) <= 1e-6 * max(abs(b), 1e-30)
    if field.startswith("sigma_"):
        top = max(abs(low), abs(high))
        ok = row["map"] == "diverging" and close(lo, -top) and close(hi, top)
    else:
        ok = row["map"] == "sequential" and lo == 0 and close(hi, high)
    shown = float(row["shown_min"]), float(row["shown_max"])
    ok = ok and lo - 1e-6 * abs(hi) <= shown[0] and shown[1] <= hi + 1e-6 * abs(hi)
    ok = ok and ranges.setdefault(field, (lo, hi)) == (lo, hi)
    print("%s, %s: %s [%.4g, %.4g]; the run's data [%.4g, %.4g]: %s"
          % (row["picture"], field, row["map"], lo, hi, low, high,
             "yes" if ok else "NO"))
    bad += not ok
sys.exit(1 if bad else 0)
PY
pictures=$(dirname "$(head -1 "$work/pngs")")
if xvfb-run -a pvpython "$work/colours.py" "$work/run" "$pictures" \
  >"$work/colour_report" 2>&1; then
  colours_ok=1
else
  colours_ok=0
fi
sed 's/^/check_render:   /' "$work/colour_report" | grep -v "^check_render:   $" || true
check "each picture's colours: one rule per field, its range the run's data (colours.csv against the VTU)" \
  test "$colours_ok" = 1

# The state, loaded as a user does (File > Load State): it opens at the
# snapshot nearest summary.txt's time_of_peak_force_us, with the plate
# warped and coloured as the stills, and holds no helpers (the sections'
# slices and thresholds, MergeBlocks): at most 6 sources.
cat >"$work/state.py" <<'PY'
import re, sys
from paraview import simple as pv
state, run = sys.argv[1], sys.argv[2]
pv.LoadState(state, data_directory=run, restrict_to_data_directory=True)
sources = pv.GetSources()
names = sorted(name for name, _ in sources)
kinds = sorted(proxy.GetXMLName() for proxy in sources.values())
peak = float(re.search(r"time_of_peak_force_us = (\S+)",
                       open(run + "/summary.txt").read()).group(1))
times = [float(t) for t in re.findall(r'timestep="([^"]+)"',
                                      open(run + "/solution.pvd").read())]
nearest = min(times, key=lambda t: abs(t - peak))
at = pv.GetAnimationScene().AnimationTime
ok = (len(sources) <= 6 and "MergeBlocks" not in kinds
      and abs(at - nearest) <= 1e-9 * max(abs(nearest), 1.0))
print("scene.pvsm: %d sources (%s); opens at t = %.4f us, the snapshot "
      "nearest the peak force's %.4f us: %.4f us: %s"
      % (len(sources), ", ".join(names), at, peak, nearest,
         "yes" if ok else "NO"))
sys.exit(0 if ok else 1)
PY
if xvfb-run -a pvpython "$work/state.py" "$pictures/scene.pvsm" "$work/run" \
  >"$work/state_report" 2>&1; then
  state_ok=1
else
  state_ok=0
fi
grep "scene.pvsm\|Error\|error" "$work/state_report" | sed 's/^/check_render:   /' || true
check "scene.pvsm opens at the peak snapshot with a clean pipeline" \
  test "$state_ok" = 1

# The report after the pictures (what a user does next): report.html embeds
# every still of pictures/ (the animation frames are in the movie).
python3 scripts/report.py "$work/run" >/dev/null
embedded=$(grep -o 'src="data:image/png;base64,' "$work/run/report.html" | wc -l)
stills=$(ls "$pictures"/*.png | wc -l)
echo "check_render:   report.html: $embedded pictures embedded, $stills stills in pictures/"
check "report.py embeds every still picture" test "$embedded" = "$stills" -a "$stills" -gt 0
exit $failed
