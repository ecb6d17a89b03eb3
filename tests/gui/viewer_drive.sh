#!/bin/sh
# Drives a running facet-view with real X input events (xdotool), inside the virtual display
# that the caller started (viewer_gui_test runs this under `xvfb-run -a`).
#
#   viewer_drive.sh SCENARIO OUTDIR VIEWER [VIEWER ARGS...]
#
# The viewer starts in OUTDIR with --state state.txt --screenshot frame.png; SCENARIO says what
# to do with the window (all coordinates relative to it), then SIGTERM ends it (see the end):
#   none    nothing
#   orbit   left drag across the image, then three wheel turns towards the scene
#   panel   left drag that starts on the side bar's title row
#   pan     right drag across the image
#   divider left drag from the middle of the window to x = 900 (the Compare divider)
#   resize  resize the window to 800x600
#   key     press P (screenshot into OUTDIR)
#   renderers  press G four times, a second apart: CPU engine → OpenGL twin → side by side →
#           CPU engine → OpenGL twin
#   combo   open the Render panel's renderer combo and click its second entry (OpenGL twin)
#   save    left drag across the image (orbit), then Ctrl+S; in the save dialog the path
#           $FACET_DRIVE_SAVE_AS (when set) and Enter
#   steps   run $FACET_DRIVE_STEPS, ';'-separated commands of this script: drag B X Y DX DY N,
#           ctrldrag X Y DX DY N, key KEY..., at X Y (move the pointer), click B, shiftclick X Y
#           (Shift + left click), press X Y (move and left click at once), pause SECONDS
# FACET_DRIVE_SETTLE sets the wait before the scenario (1 s by default).
set -u
scenario=$1
out=$2
shift 2
cd "$out" || exit 1

"$@" --state state.txt --screenshot frame.png >viewer.log 2>&1 &
pid=$!

# The window exists once it is mapped; give up after 20 s rather than hang the test.
wid=$(timeout 20 xdotool search --sync --onlyvisible --name '^facet-view' 2>/dev/null | head -n 1)
if [ -z "$wid" ]; then
  echo "viewer_drive: no facet-view window appeared" >&2
  kill -TERM "$pid" 2>/dev/null
  wait "$pid"
  exit 1
fi
# Let it draw a few frames and lay out its panels (FACET_DRIVE_SETTLE seconds: a test that must
# act while a file loads waits less).
sleep "${FACET_DRIVE_SETTLE:-1}"

# A drag in small steps with pauses: each step lands in a different frame.
drag() {  # button x0 y0 dx dy steps
  b=$1 x=$2 y=$3 dx=$4 dy=$5 n=$6
  xdotool mousemove --window "$wid" "$x" "$y"
  sleep 0.2
  xdotool mousedown "$b"
  sleep 0.2
  i=1
  while [ "$i" -le "$n" ]; do
    xdotool mousemove --window "$wid" $((x + dx * i / n)) $((y + dy * i / n))
    sleep 0.1
    i=$((i + 1))
  done
  xdotool mouseup "$b"
  sleep 0.3
}

ctrldrag() {  # x0 y0 dx dy steps, left button with Ctrl held
  xdotool keydown ctrl
  drag 1 "$@"
  xdotool keyup ctrl
}
at() { xdotool mousemove --window "$wid" "$1" "$2"; sleep 0.1; }
key() { xdotool key "$@"; sleep 0.4; }
click() { xdotool click "$1"; sleep 0.3; }
shiftclick() {  # x y: left click with Shift held (the pixel inspector)
  at "$1" "$2"
  xdotool keydown shift
  sleep 0.2
  xdotool click 1
  sleep 0.2
  xdotool keyup shift
  sleep 0.5
}
pause() { sleep "$1"; }
press() {  # x y: move there and click at once, in one xdotool call (often within one frame)
  xdotool mousemove --window "$wid" "$1" "$2" mousedown 1 mouseup 1
  sleep 0.5
}

case "$scenario" in
  none) ;;
  save)
    drag 1 800 450 150 -40 6
    xdotool key --window "$wid" ctrl+s
    sleep 0.7
    # The first save asks where: the path field has the focus; FACET_DRIVE_SAVE_AS replaces it.
    if [ -n "${FACET_DRIVE_SAVE_AS:-}" ]; then
      xdotool key ctrl+a
      xdotool type --delay 10 "$FACET_DRIVE_SAVE_AS"
      sleep 0.3
    fi
    # Held for a frame: ImGui sees keys by their state once a frame, not by their events.
    xdotool keydown Return
    sleep 0.15
    xdotool keyup Return
    sleep 1
    ;;
  orbit)
    drag 1 800 450 120 60 6
    xdotool mousemove --window "$wid" 800 450
    for _ in 1 2 3; do xdotool click 4; sleep 0.15; done
    ;;
  panel) drag 1 120 19 160 120 6 ;;
  pan) drag 3 800 450 100 50 5 ;;
  divider) drag 1 1020 450 260 0 5 ;;
  resize) xdotool windowsize "$wid" 800 600; sleep 1 ;;
  key) xdotool mousemove --window "$wid" 800 450; sleep 0.2; xdotool key p; sleep 0.5 ;;
  renderers)
    xdotool mousemove --window "$wid" 800 450
    for _ in 1 2 3 4; do sleep 1; xdotool key g; done
    sleep 1
    ;;
  combo)
    # The combo is the Render panel's first row, open at start (the side bar at the left).
    xdotool mousemove --window "$wid" 110 114 click 1
    sleep 0.5
    xdotool mousemove --window "$wid" 110 155 click 1
    sleep 1
    ;;
  steps) eval "${FACET_DRIVE_STEPS:-}" ;;
  *) echo "viewer_drive: unknown scenario $scenario" >&2 ;;
esac

sleep 0.5
# Esc never quits (it closes the innermost thing); Ctrl+Q asks first when the scene changed.
# So the run ends with SIGTERM, which finishes the frame and writes the outputs, unless
# FACET_DRIVE_QUIT=wait: then the scenario itself quit (Ctrl+Q) and the viewer must end alone.
case "${FACET_DRIVE_QUIT:-term}" in
  wait) ;;
  *) kill -TERM "$pid" ;;
esac
i=0
while kill -0 "$pid" 2>/dev/null && [ "$i" -lt 50 ]; do sleep 0.1; i=$((i + 1)); done
if kill -0 "$pid" 2>/dev/null; then
  echo "viewer_drive: the viewer was still running; sending SIGTERM"
  kill -TERM "$pid"
fi
wait "$pid"
status=$?
echo "viewer exit $status"
exit "$status"
