#!/usr/bin/env bash
# Regenerates the golden frames in tests/golden/<id>/ for one demo id, several, or 'all' (every demo and scene).
#   scripts/update-goldens.sh ID... | scene:NAME... | scenes | all   (env BUILD_DIR: build tree, default build)
# scene:NAME is the scene file scenes/NAME.json, with goldens in tests/golden/scenes/NAME/; 'scenes' is every one.
# Each folder keeps run.args, the arguments its goldens were made with (one per line); CTest's golden.<id> and
# golden.scene.<name> tests read the same file, so both always render the same frames. A new folder gets the
# default arguments below; edit run.args (e.g. add --set lines) and rerun to change them.
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${BUILD_DIR:-$repo/build}"
exe="$build/physics-sandbox"
default_args=(--size 640x480 --frames 91 --only-frames 0,30,90)
# Scenes: small and without panels (the demos' goldens cover the panels), 2 s of motion.
scene_args=(--size 320x240 --no-ui --frames 121 --only-frames 0,60,120)

if [ $# -eq 0 ] || [ "$1" = "-h" ] || [ "$1" = "--help" ]; then
  sed -n '2,7p' "$0" | sed 's/^# \{0,1\}//'
  exit 2
fi
if [ ! -x "$exe" ]; then
  echo "update-goldens: $exe not found; build first (cmake --build $build --target physics-sandbox)" >&2
  exit 2
fi

all_scenes() {
  for f in "$repo"/scenes/*.json; do
    case "$f" in *.schema.json) ;; *) name=${f##*/}; echo "scene:${name%.json}" ;; esac
  done
}

ids=()
for arg in "$@"; do
  case "$arg" in
    all)
      while IFS=$'\t' read -r id _; do ids+=("$id"); done < <("$exe" --list)
      mapfile -t -O "${#ids[@]}" ids < <(all_scenes) ;;
    scenes) mapfile -t -O "${#ids[@]}" ids < <(all_scenes) ;;
    *) ids+=("$arg") ;;
  esac
done

status=0
for id in "${ids[@]}"; do
  if [ "${id#scene:}" != "$id" ]; then
    name=${id#scene:}
    what=(--scene "$repo/scenes/$name.json")
    dir="$repo/tests/golden/scenes/$name"
    defaults=("${scene_args[@]}")
    [ -f "$repo/scenes/$name.json" ] || { echo "update-goldens: no scenes/$name.json" >&2; status=1; continue; }
  else
    what=(--demo "$id")
    dir="$repo/tests/golden/$id"
    defaults=("${default_args[@]}")
  fi
  mkdir -p "$dir"
  if [ ! -f "$dir/run.args" ]; then printf '%s\n' "${defaults[@]}" > "$dir/run.args"; fi
  mapfile -t args < "$dir/run.args"
  rm -f "$dir"/frame_*.png
  if "$exe" "${what[@]}" "${args[@]}" --compare "$dir" --update-golden --png-level 9 --quiet; then
    echo "update-goldens: $id: $(cd "$dir" && ls frame_*.png | tr '\n' ' ')"
  else
    echo "update-goldens: $id failed" >&2
    status=1
  fi
done
exit $status
