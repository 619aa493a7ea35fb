#!/usr/bin/env bash
# The interactive window under Xvfb, driven as a person would with xdotool: it opens the book's 800x600
# "Physics Sandbox" window on ch14, clicks the panel's "Run Chapter 15" button, right-drags (rotate) and
# middle-drags (zoom) over the scene, and takes screenshots (ffmpeg's x11grab) along the way. It checks that
# the demo changed (the program's "demo:" lines and the pixels) and that the view changed (the camera in the
# closing summary; the scene's pixels, which the animation changes too, are a weaker second check). Exit 77
# (skipped, saying why) without Xvfb, xdotool, ffmpeg or cmp.
# Usage: window_test.sh PATH/TO/physics-sandbox SCRATCH_DIR
set -u
exe=$1
dir=$2
rm -rf "$dir" && mkdir -p "$dir"
for tool in Xvfb xdotool ffmpeg cmp; do
  command -v "$tool" >/dev/null 2>&1 || { echo "window: skipped: '$tool' is not installed (scripts/install-deps.sh)"; exit 77; }
done
fail() { echo "window: FAIL: $*" >&2; echo "--- program output:" >&2; cat "$dir/app.out" "$dir/app.err" >&2 2>/dev/null; exit 1; }

# A private display: Xvfb picks a free number and writes it to fd 3.
exec 3>"$dir/display"
Xvfb -displayfd 3 -screen 0 1024x768x24 -nolisten tcp >"$dir/xvfb.log" 2>&1 &
xvfb=$!
exec 3>&-
app=
cleanup() { [ -n "$app" ] && kill "$app" 2>/dev/null; kill "$xvfb" 2>/dev/null; wait 2>/dev/null; }
trap cleanup EXIT
for _ in $(seq 50); do [ -s "$dir/display" ] && break; sleep 0.1; done
[ -s "$dir/display" ] || fail "Xvfb did not start: $(cat "$dir/xvfb.log")"
export DISPLAY=":$(head -n 1 "$dir/display")"

# 720 frames: at most 62.5 per second (the book's frame limiter), so at least 11.5 s for the steps below.
"$exe" --window --demo ch14 --frames 720 >"$dir/app.out" 2>"$dir/app.err" &
app=$!
wid=$(timeout 20 xdotool search --sync --name '^Physics Sandbox$' | head -n 1)
[ -n "$wid" ] || fail "no window named 'Physics Sandbox' appeared"
size=$(xdotool getwindowgeometry "$wid" | awk '/Geometry/ {print $2}')
[ "$size" = 800x600 ] || fail "the window is $size, not the book's 800x600"

waitfor() {  # waitfor TEXT SECONDS: until the program has printed TEXT
  for _ in $(seq $(($2 * 10))); do grep -qx -- "$1" "$dir/app.out" && return 0; sleep 0.1; done
  return 1
}
shot() {  # shot NAME: the window's 800x600 as raw RGB, whole and its scene part (below the panels)
  ffmpeg -v error -y -f x11grab -video_size 800x600 -i "$DISPLAY+0,0" -frames:v 1 "$dir/$1.png" || fail "screenshot $1"
  ffmpeg -v error -y -i "$dir/$1.png" -vf crop=800:480:0:120 -f rawvideo -pix_fmt rgb24 "$dir/$1.scene" ||
    fail "crop $1"
  # The panel's button row only (the row above shows the live frame rate, which changes every frame).
  ffmpeg -v error -y -i "$dir/$1.png" -vf crop=370:22:10:52 -f rawvideo -pix_fmt rgb24 "$dir/$1.panel" ||
    fail "crop $1"
}

waitfor "demo: ch14" 10 || fail "ch14 did not start"
sleep 1
shot ch14
# The panel's second button, " Run Chapter 15" (docs/book-reference.md §1.7), at (195, 63) in the window.
xdotool mousemove --window "$wid" 195 63 click 1
waitfor "demo: ch15" 5 || fail "clicking 'Run Chapter 15' did not start ch15"
sleep 1.5
shot ch15
cmp -s "$dir/ch14.scene" "$dir/ch15.scene" && fail "the scene looks the same after switching demos"
cmp -s "$dir/ch14.panel" "$dir/ch15.panel" && fail "the panel's buttons look the same after switching demos"
shot ch15b
cmp -s "$dir/ch15.panel" "$dir/ch15b.panel" || fail "the panel's buttons change by themselves (the check above means nothing)"

# Right drag rotates, middle drag zooms (the book's camera, docs/book-reference.md §1.1).
# As a person would, the pointer arrives before the press: ImGui decides whether it wants a press from the
# frame before (the book forwards presses only when ImGui does not want the mouse).
xdotool mousemove --window "$wid" 400 400
sleep 0.2
xdotool mousedown 3
for x in 420 440 460 480 500; do xdotool mousemove --window "$wid" $x 400; sleep 0.05; done
xdotool mouseup 3
sleep 0.3
xdotool mousemove --window "$wid" 400 300
sleep 0.2
xdotool mousedown 2
for y in 320 340 360 380; do xdotool mousemove --window "$wid" 400 $y; sleep 0.05; done
xdotool mouseup 2
sleep 0.5
shot moved
cmp -s "$dir/ch15.scene" "$dir/moved.scene" && fail "the scene looks the same after dragging the camera"

wait "$app"
rc=$?
app=
[ "$rc" -eq 0 ] || fail "the program exited $rc"
summary=$(grep '^window:' "$dir/app.out") || fail "no closing summary"
echo "$summary" | grep -q "demo ch15," || fail "summary names another demo: $summary"
# ch15 starts from the book's preset: yaw -67.9312, pitch 19.8, zoom 12.
yaw=$(echo "$summary" | sed -n 's/.*camera yaw \([-0-9.]*\).*/\1/p')
zoom=$(echo "$summary" | sed -n 's/.* zoom \([-0-9.]*\).*/\1/p')
[ -n "$yaw" ] && [ -n "$zoom" ] || fail "summary has no camera: $summary"
[ "$yaw" != "-67.9312" ] || fail "right drag did not rotate the camera: $summary"
[ "$zoom" != "12.0000" ] || fail "middle drag did not zoom the camera: $summary"

# model: auto in the window (docs/app.md, "Error budget"): chosen before the first frame, its summary after the
# window's; a budget no candidate meets closes it with exit 2 before any frame.
"$exe" --window --demo springs --set model=auto --set tolerance=0.01 --frames 30 >"$dir/app.out" 2>"$dir/app.err" ||
  fail "the window with model=auto exited $?"
grep -q '^Model: auto, ' "$dir/app.out" || fail "no auto model summary"
"$exe" --window --demo springs --set model=auto --set tolerance=1e-9 --frames 30 >"$dir/app.out" 2>"$dir/app.err"
rc=$?
[ "$rc" -eq 2 ] || fail "an impossible budget in the window exited $rc, not 2"
grep -q 'the budget over the safety factor' "$dir/app.err" || fail "the refusal says not what the safety factor asks"

# Standard output on a full device: the demo lines and the summary are lost, so exit 3 with a message, as the
# headless runs do (docs/app.md, "Exit codes").
"$exe" --window --demo ch14 --frames 5 >/dev/full 2>"$dir/app.err"
rc=$?
[ "$rc" -eq 3 ] || fail "--window with stdout on /dev/full exited $rc, not 3"
grep -q 'cannot write to standard output' "$dir/app.err" || fail "no message for the lost standard output"
echo "window: ok (ch14 -> ch15 by the panel button; camera yaw $yaw, zoom $zoom after the drags; model=auto; stdout on /dev/full)"
