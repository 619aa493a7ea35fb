#!/usr/bin/env bash
# Draws docs/sweep/contact-convergence.png from psb-contact-convergence's CSV (docs/soft-solver.md, "Convergence of the
# contact solvers"): one panel per problem, error (m) against the substep h = dt / substeps (s) on log-log axes,
# one line per solver (the soft solver one line per substep count, over the step), and the 1 mm line. The particle
# bounce is drawn against the step dt: particles are not substepped by the contact solvers.
#   scripts/plot-contact-convergence.sh [CSV] [-o PNG]
# Defaults: docs/sweep/contact-convergence.csv -> docs/sweep/contact-convergence.png. Needs gnuplot.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
csv="$root/docs/sweep/contact-convergence.csv"
png="$root/docs/sweep/contact-convergence.png"
while [ $# -gt 0 ]; do
  case "$1" in
    -o) png="$2"; shift 2 ;;
    -h|--help) sed -n '2,6p' "$0"; exit 0 ;;
    *) csv="$1"; shift ;;
  esac
done
[ -r "$csv" ] || { echo "plot-contact-convergence: cannot read '$csv'" >&2; exit 2; }
command -v gnuplot >/dev/null || { echo "plot-contact-convergence: gnuplot not found (scripts/install-deps.sh)" >&2; exit 1; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

# Columns: 1 problem, 2 solver, 3 dt, 4 substeps, 5 h, 6 error_m, 7 cpu_s. One data file per problem and series,
# rows by decreasing h.
awk -F, -v dir="$work" 'NR > 1 {
    s = ($2 == "soft") ? "soft-" $4 : $2
    f = dir "/" $1 "@" s ".dat"
    x = ($1 == "particle-bounce") ? $3 : $5  # a particle sees the step, not the volume substeps
    print x, ($6 > 1e-9 ? $6 : 1e-9) >> f
  }' "$csv"
problems=$(awk -F, 'NR > 1 { print $1 }' "$csv" | awk '!seen[$0]++')
count=$(echo "$problems" | wc -l)
rows=$(( (count + 1) / 2 ))

{
  echo "set terminal pngcairo size 1400,$((rows * 380)) font ',10'"
  echo "set output '$png'"
  echo "set multiplot layout $rows,2"
  echo "set logscale xy; set format x '%.0e'; set format y '%.0e'; set grid"
  echo "set xlabel 'substep h = dt / substeps (s)'; set ylabel 'error vs exact (m)'"
  echo "set key outside right top font ',8'; set xrange [*:*] reverse"
  for p in $problems; do
    if [ "$p" = particle-bounce ]; then
      echo "set title '$p (against the step dt)'; set xlabel 'step dt (s)'"
    else
      echo "set title '$p'; set xlabel 'substep h = dt / substeps (s)'"
    fi
    plot="plot 1e-3 with lines dashtype 2 lc 'black' title '1 mm'"
    for f in "$work/$p@"*.dat; do
      series="${f##*@}"; series="${series%.dat}"
      sort -g -r -k1,1 "$f" -o "$f"
      plot="$plot, '$f' using 1:2 with linespoints pt 7 ps 0.6 title '${series/soft-/soft sub=}'"
    done
    echo "$plot"
  done
  echo "unset multiplot"
} > "$work/plot.gp"
gnuplot "$work/plot.gp"
echo "plot-contact-convergence: wrote $png"
