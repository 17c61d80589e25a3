#!/usr/bin/env bash
# Render the standard pictures of an fgimpact run (scripts/render.py) with
# ParaView's pvpython, headless: through xvfb-run when there is no DISPLAY.
# Debian 12's ParaView 5.11 crashes with --force-offscreen-rendering, and
# under xvfb-run it sometimes connects before the X server is ready ("bad
# X server connection", SIGABRT, measured in 2 of 4 runs on a loaded
# machine): that failure alone is retried, up to 4 times.
#   scripts/render.sh OUTPUT_DIR [render.py options]
set -uo pipefail
here=$(dirname "$0")
command -v pvpython >/dev/null || {
  echo "render.sh: pvpython not found (apt-get install paraview python3-paraview xvfb)" >&2
  exit 2
}
if [ -n "${DISPLAY:-}" ]; then
  exec pvpython "$here/render.py" "$@"
fi
log=$(mktemp)
trap 'rm -f "$log"' EXIT
for attempt in 1 2 3 4; do
  xvfb-run -a -s "-screen 0 1600x1200x24" pvpython "$here/render.py" "$@" 2>"$log"
  status=$?
  if [ $status -eq 0 ] || ! grep -q "bad X server connection" "$log"; then
    # libswscale's note on the movie's JPEG pixel format is not a problem.
    grep -v -e "^\s*$" -e "deprecated pixel format used" "$log" >&2
    exit $status
  fi
  sleep 1
done
echo "render.sh: the X server (xvfb-run) did not accept pvpython in 4 attempts" >&2
exit 1
