#!/usr/bin/env bash
# Recording cost: wall time of a run that records every frame with --video against the same run writing every
# frame as PNG (--out), alternated in one shell so both see the same machine. Prints one line per demo and
# format: demo, frames, format, png_s, video_s, ratio (medians of ROUNDS alternations). The target (docs/app.md,
# "Video") is ratio <= 1.3: ffmpeg encodes in its own process while the next frames render.
# Usage: bench/video_bench.sh [BUILD_DIR] [FRAMES] [ROUNDS]
set -euo pipefail
build=${1:-build}
frames=${2:-600}
rounds=${3:-3}
exe=$build/physics-sandbox
[ -x "$exe" ] || { echo "video_bench: no $exe" >&2; exit 2; }
command -v ffmpeg >/dev/null || { echo "video_bench: ffmpeg is not installed" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
seconds() { local t0 t1; t0=$(date +%s.%N); "$@" >/dev/null 2>&1; t1=$(date +%s.%N); awk -v a="$t0" -v b="$t1" 'BEGIN {print b - a}'; }
median() { sort -g | awk '{a[NR] = $1} END {print a[int((NR + 1) / 2)]}'; }
for demo in ch14 ch15 ch16; do
  for format in mp4 webm gif; do
    png=() video=()
    for _ in $(seq "$rounds"); do
      rm -rf "$work"/*
      png+=("$(seconds "$exe" --demo "$demo" --frames "$frames" --out "$work/png" --quiet)")
      video+=("$(seconds "$exe" --demo "$demo" --frames "$frames" --video "$work/run.$format" --quiet)")
    done
    p=$(printf '%s\n' "${png[@]}" | median)
    v=$(printf '%s\n' "${video[@]}" | median)
    printf 'demo=%s frames=%s format=%s png_s=%.2f video_s=%.2f ratio=%.2f\n' "$demo" "$frames" "$format" "$p" "$v" \
      "$(awk -v a="$v" -v b="$p" 'BEGIN {print a / b}')"
  done
done
