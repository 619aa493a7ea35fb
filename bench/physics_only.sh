#!/usr/bin/env bash
# Runs without pictures (docs/app.md, "Runs without pictures"): wall time of `--state` alone, which makes no GL
# context and draws nothing, against the same run writing every frame with --out, alternated in one shell so
# both see the same machine. Checks that both state CSVs are byte-identical, then prints one line per demo:
# demo, frames, state_s, out_s, speedup (medians of ROUNDS alternations). Target: speedup >= 5 for ch16.
# Usage: bench/physics_only.sh [BUILD_DIR] [FRAMES] [ROUNDS] [DEMO...]   (default: build 300 3 ch16)
set -euo pipefail
build=${1:-build}
frames=${2:-300}
rounds=${3:-3}
shift $(($# < 3 ? $# : 3))
demos=("$@")
[ ${#demos[@]} -gt 0 ] || demos=(ch16)
exe=$build/physics-sandbox
[ -x "$exe" ] || { echo "physics_only: no $exe" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
seconds() { local t0 t1; t0=$(date +%s.%N); "$@" >/dev/null 2>&1; t1=$(date +%s.%N); awk -v a="$t0" -v b="$t1" 'BEGIN {print b - a}'; }
median() { sort -g | awk '{a[NR] = $1} END {print a[int((NR + 1) / 2)]}'; }
for demo in "${demos[@]}"; do
  bare=() drawn=()
  for _ in $(seq "$rounds"); do
    rm -rf "${work:?}"/*
    bare+=("$(seconds "$exe" --demo "$demo" --frames "$frames" --state "$work/bare.csv" --quiet)")
    drawn+=("$(seconds "$exe" --demo "$demo" --frames "$frames" --state "$work/drawn.csv" --out "$work/png" --quiet)")
    cmp -s "$work/bare.csv" "$work/drawn.csv" || { echo "physics_only: $demo: the state CSVs differ" >&2; exit 1; }
  done
  b=$(printf '%s\n' "${bare[@]}" | median)
  d=$(printf '%s\n' "${drawn[@]}" | median)
  printf 'demo=%s frames=%s state_s=%.2f out_s=%.2f speedup=%.1f\n' "$demo" "$frames" "$b" "$d" \
    "$(awk -v a="$d" -v b="$b" 'BEGIN {print a / b}')"
done
