#!/bin/sh
# scripts/check-scenes.py on scenes written here, against the shipped schema: a scene with the soft solver's
# settings and each form of world.sleep passes; a key given twice, a soft setting out of range and a sleep of the
# wrong type fail, each named. Usage: check_scenes_test.sh REPO_ROOT PYTHON SCRATCH_DIR
set -eu
root=$1
python=$2
dir=$3
rm -rf "$dir" && mkdir -p "$dir/scenes"
fail() { echo "scenes.schema-check: FAIL: $*" >&2; exit 1; }
cp "$root/scenes/scene.schema.json" "$dir/scenes/"
body='"bodies": [{"id": "a", "type": "box", "position": [0, 1, 0]}]'

# expect_top OK|FAIL MEMBERS [MESSAGE]: one scene with the top-level MEMBERS checked alone.
expect_top() {
  rm -f "$dir/scenes/t.json"
  printf '{"format": 1, "name": "t", %s, %s}\n' "$2" "$body" >"$dir/scenes/t.json"
  set +e
  "$python" "$root/scripts/check-scenes.py" "$dir" >"$dir/out.txt" 2>&1
  rc=$?
  set -e
  if [ "$1" = OK ]; then
    [ "$rc" -eq 0 ] || fail "refused $2: $(cat "$dir/out.txt")"
  else
    [ "$rc" -eq 1 ] || fail "accepted $2 (exit $rc)"
    grep -qF "$3" "$dir/out.txt" || fail "for $2 the message lacks '$3': $(cat "$dir/out.txt")"
  fi
}

# expect OK|FAIL WORLD [MESSAGE]: one scene with "world": WORLD checked alone.
expect() { expect_top "$1" "\"world\": $2" "${3:-}"; }

expect OK '{"contactSolver": "soft", "soft": {"substeps": 8, "contactHertz": 60, "relaxIterations": 0}}'
expect OK '{"sleep": true}'
expect OK '{"sleep": false}'
expect OK '{"sleep": {"enabled": true, "timeToSleep": 1, "linearSpeed": 0.1, "angularSpeed": 0.2}}'
expect FAIL '{"soft": {"substeps": 0}}' 'world.soft.substeps: must be >= 1'
expect FAIL '{"soft": {"contactHertz": 2000}}' 'world.soft.contactHertz: must be <= 1000'
expect FAIL '{"soft": {"hertz": 30}}' 'world.soft.hertz: unknown key'
expect FAIL '{"sleep": 1}' 'world.sleep: must match exactly one of 2 forms'
expect FAIL '{"sleep": {"time": 1}}' 'world.sleep: must match exactly one of 2 forms'
expect FAIL '{"iterations": 5, "iterations": 9}' "duplicate key 'iterations'"
# The error budget (docs/scenes.md, "Error budget").
expect_top OK '"model": "auto", "budget": {"quantity": "energy", "bound": 0.01}'
expect_top OK '"model": "fixed", "budget": {"bound": 1}'
expect_top FAIL '"model": "best"' 'model: must be one of'
expect_top FAIL '"model": "auto", "budget": {"bound": 0}' 'budget.bound: must be >= 1e-09'
expect_top FAIL '"model": "auto", "budget": {"quantity": "position"}' 'budget.bound: is required'
# Nesting past the loader's 64 levels (the object itself is one): refused before parsing, as the loader does.
expect_top FAIL '"extra": [[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]' 'nest 65 levels deep, over the limit of 64'
expect_top FAIL '"name2": "[[[[", "extra": [[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]' 'nest 65 levels deep'
expect_top FAIL '"model": "auto", "budget": {"quantity": "speed", "bound": 1}' 'budget.quantity: must be one of'
echo "scenes.schema-check: ok"
