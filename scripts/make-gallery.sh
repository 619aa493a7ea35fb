#!/usr/bin/env bash
# The README's animated gallery: a short, small GIF of each demo (docs/images/<id>.gif), recorded with
# physics-sandbox --video (palettegen/paletteuse: the book's colours stay exact). 4 s at 25 frames per
# second, 360x270, panels off. Usage: scripts/make-gallery.sh [BUILD_DIR]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
exe=${1:-$root/build}/physics-sandbox
[ -x "$exe" ] || { echo "make-gallery: no $exe (build first)" >&2; exit 2; }
for id in $("$exe" --list | cut -f1); do
  "$exe" --demo "$id" --frames 100 --fps 25 --size 360x270 --no-ui --video "$root/docs/images/$id.gif" --quiet
  echo "make-gallery: docs/images/$id.gif ($(stat -c %s "$root/docs/images/$id.gif") bytes)"
done
