#!/bin/sh
# The physics-only physics-sandbox of a PSB_WITH_RENDERING=OFF build (docs/app.md, "Runs without pictures"): it
# links no GL library, runs a demo and a scene file with --state (one row per body per frame), and refuses
# --out with exit 2 and nothing written.
# Usage: physics_only_off_test.sh EXE REPO WORK
exe=$1
repo=$2
work=$3
fail() {
  echo "physics-only.off: FAIL: $*"
  exit 1
}
rm -rf "$work"
mkdir -p "$work"
if ldd "$exe" | grep -E 'lib(GL|GLX|EGL|OpenGL|OSMesa|glfw)[.-]'; then fail "links a GL library"; fi

"$exe" --demo ch16 --frames 20 --state "$work/ch16.csv" --quiet || fail "ch16 --state exited $?"
rows=$(($(wc -l < "$work/ch16.csv") - 1))
[ "$rows" -eq $((20 * 225)) ] || fail "ch16: $rows state rows, expected 20 frames x 225 cloth particles"
"$exe" --scene "$repo/scenes/newtons-cradle.json" --frames 20 --state "$work/cradle.csv" --quiet ||
  fail "newtons-cradle --state exited $?"
[ "$(grep -c '^19,' "$work/cradle.csv")" -gt 0 ] || fail "newtons-cradle: no rows for frame 19"

"$exe" --demo ch16 --frames 2 --out "$work/frames" 2> "$work/err.txt"
code=$?
[ "$code" -eq 2 ] || fail "--out exited $code, expected 2"
grep -q "PSB_WITH_RENDERING=OFF" "$work/err.txt" || fail "--out: message does not name the build option: $(cat "$work/err.txt")"
[ ! -e "$work/frames" ] || fail "--out: $work/frames was created"
echo "physics-only.off: no GL library linked; ch16 and newtons-cradle ran with --state; --out refused"
