#!/bin/sh
# Every shipped scene file (scenes/*.json, not scenes/reference/ or the schema) has goldens in
# tests/golden/scenes/<name>/ with a run.args, so CTest registers golden.scene.<name> for it.
# Usage: scene_goldens_test.sh REPO
repo=$1
missing=0
for f in "$repo"/scenes/*.json; do
  name=${f##*/}
  name=${name%.json}
  case $name in *.schema) continue ;; esac
  if [ ! -f "$repo/tests/golden/scenes/$name/run.args" ]; then
    echo "scene_goldens: scenes/$name.json has no tests/golden/scenes/$name/run.args (scripts/update-goldens.sh scene:$name)"
    missing=1
  fi
done
exit $missing
