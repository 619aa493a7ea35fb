#!/usr/bin/env bash
# Regenerates the golden frames in tests/golden/<id>/ for one demo id, several, or 'all'.
#   scripts/update-goldens.sh ID... | all        (env BUILD_DIR: build tree with physics-sandbox, default build)
# Each demo folder keeps run.args, the arguments its goldens were made with (one per line); CTest's
# golden.<id> test reads the same file, so both always render the same frames. A new folder gets the
# default arguments below; edit run.args (e.g. add --set lines) and rerun to change them.
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${BUILD_DIR:-$repo/build}"
exe="$build/physics-sandbox"
default_args=(--size 640x480 --frames 91 --only-frames 0,30,90)

if [ $# -eq 0 ] || [ "$1" = "-h" ] || [ "$1" = "--help" ]; then
  sed -n '2,6p' "$0" | sed 's/^# \{0,1\}//'
  exit 2
fi
if [ ! -x "$exe" ]; then
  echo "update-goldens: $exe not found; build first (cmake --build $build --target physics-sandbox)" >&2
  exit 2
fi

ids=()
if [ "$1" = "all" ]; then
  while IFS=$'\t' read -r id _; do ids+=("$id"); done < <("$exe" --list)
else
  ids=("$@")
fi

status=0
for id in "${ids[@]}"; do
  dir="$repo/tests/golden/$id"
  mkdir -p "$dir"
  if [ ! -f "$dir/run.args" ]; then printf '%s\n' "${default_args[@]}" > "$dir/run.args"; fi
  mapfile -t args < "$dir/run.args"
  rm -f "$dir"/frame_*.png
  if "$exe" --demo "$id" "${args[@]}" --compare "$dir" --update-golden --png-level 9 --quiet; then
    echo "update-goldens: $id: $(cd "$dir" && ls frame_*.png | tr '\n' ' ')"
  else
    echo "update-goldens: $id failed" >&2
    status=1
  fi
done
exit $status
