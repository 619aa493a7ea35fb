#!/usr/bin/env bash
# Turns psb-sweep CSV output into the PNG figures of docs/sweep.md (gnuplot, from gnuplot-nox).
#   scripts/plot-sweep.sh [CSV...] [-o OUTDIR] [--auto AUTO_CSV]
# Defaults: docs/sweep/results.csv -> docs/sweep/. Several CSVs (shards) are merged; repeated headers skipped.
# --auto: the points of `model: auto` (psb-model-choice-bench --csv, docs/model-choice-validation.md) are added to
# the error-against-cost figures as red triangles labelled with their budget; default docs/sweep/auto.csv if present.
# Axis labels come from problems.tsv (psb-sweep --list) beside the first CSV, when present.
# Per problem: error against CPU cost (s per simulated s) on log-log axes, one line per integrator or solver
# setting, the Pareto front (no cheaper run is as accurate) as a black dashed line. For spring-stiffness,
# cloth (+ cloth-stiffness) and stack-mass-ratio: a stability map, step size against stiffness or mass ratio,
# one panel per integrator (or per contact solver and iteration count), each run coloured stable / inaccurate /
# unstable.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out="$root/docs/sweep"
inputs=()
auto="$root/docs/sweep/auto.csv"
while [ $# -gt 0 ]; do
  case "$1" in
    -o) out="$2"; shift 2 ;;
    --auto) auto="$2"; [ -r "$auto" ] || { echo "plot-sweep: cannot read '$auto'" >&2; exit 2; }; shift 2 ;;
    -h|--help) sed -n '2,10p' "$0"; exit 0 ;;
    *) inputs+=("$1"); shift ;;
  esac
done
[ ${#inputs[@]} -gt 0 ] || inputs=("$root/docs/sweep/results.csv")
units="$(dirname "${inputs[0]}")/problems.tsv"
for f in "${inputs[@]}"; do
  [ -r "$f" ] || { echo "plot-sweep: cannot read '$f'" >&2; exit 2; }
done
command -v gnuplot >/dev/null || { echo "plot-sweep: gnuplot not found (scripts/install-deps.sh)" >&2; exit 1; }
mkdir -p "$out"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

# Merge: keep one header, sort rows by run index so shards give the same file as one process.
{ head -n 1 "${inputs[0]}"; for f in "${inputs[@]}"; do tail -n +2 "$f"; done | sort -t, -k1,1n; } > "$work/all.csv"

# Columns: 1 run, 2 problem, 3 integrator, 4 dt, 5 substeps, 6 iterations, 7 projection, 8 solver, 9 param,
# 10 error, 11 cpu_per_sim_s, 12 stable, 13 steps, 14 sim_s, 15 note, 16 soft_substeps .. 25 (the soft solver's
# settings; '-' on other rows, absent in CSVs written before it).
series_name() {  # awk snippet: the legend of a row
  cat <<'AWK'
function series(   s) {
  if ($3 != "-") s = $3; else if ($8 != "-") s = $8; else s = "volumes";
  if ($6 != "-") s = s " it=" $6;
  if ($7 != "-") s = s " proj=" ($7 == "1" ? "on" : "off");
  if ($5 != "1") s = s " sub=" $5;
  if (NF >= 16 && $16 != "-") s = s " soft-substeps=" $16;
  if ($9 != "-" && multi) s = s " " pname "=" $9;
  return s;
}
AWK
}

problems=$(awk -F, 'NR > 1 { print $2 }' "$work/all.csv" | awk '!seen[$0]++')
maps="spring-stiffness cloth-stiffness stack-mass-ratio"

# A problem swept over several physical values (bounce e) gets one figure per value: the lines and the Pareto
# front then compare settings on the same physics.
for p in $problems; do
  case " $maps " in *" $p "*) continue ;; esac
  for v in $(awk -F, -v p="$p" 'NR > 1 && $2 == p { print $9 }' "$work/all.csv" | awk '!seen[$0]++'); do
  name="$p"; [ "$v" = "-" ] || [ "$(awk -F, -v p="$p" 'NR > 1 && $2 == p { c[$9] = 1 } END { print length(c) }' "$work/all.csv")" = 1 ] || name="$p-$v"
  dir="$work/$name"
  mkdir -p "$dir"
  # One file per series: "cost error", stable runs only, floors so log axes accept exact answers.
  awk -F, -v p="$p" -v v="$v" -v dir="$dir" -v multi=0 -v pname="" \
    "$(series_name)"'
    NR > 1 && $2 == p && $9 == v && $12 == 1 && $10 != "inf" && $10 != "nan" {
      s = series(); f = dir "/" s ".dat"; gsub(/ /, "_", f);
      if (!(f in files)) { files[f] = s; order[++n] = f }
      e = $10 + 0; if (e < 1e-9) e = 1e-9; c = $11 + 0; if (c < 1e-8) c = 1e-8;
      print c, e > f
    }
    END { for (i = 1; i <= n; i++) print order[i] "\t" files[order[i]] > (dir "/index") }' "$work/all.csv"
  [ -s "$dir/index" ] || continue
  # Pareto front over every stable run: by cost, keep a run only if it beats every cheaper one.
  cat "$dir"/*.dat | sort -g -k1,1 -k2,2 | awk 'BEGIN { best = 1e300 } $2 < best { best = $2; print }' > "$dir/pareto"
  # Axis label from `psb-sweep --list` saved next to the CSV (docs/sweep/problems.tsv), if present.
  unit=""
  [ -r "$units" ] && unit=$(awk -F'\t' -v p="$p" '$1 == p { print $2 }' "$units")
  [ -n "$unit" ] || unit="error"
  plot=""
  while IFS=$'\t' read -r file title; do
    sort -g -k1,1 "$file" -o "$file"
    pt=7; case "$title" in accumulated*) pt=5 ;; esac  # squares for the accumulated solver, circles otherwise
    plot+="'$file' using 1:2 with linespoints lw 2 pt $pt ps 0.8 title '$title', "
  done < "$dir/index"
  plot+="'$dir/pareto' using 1:2 with linespoints lw 2 dt 2 pt 6 ps 1.6 lc rgb 'black' title 'Pareto front'"
  # Auto's runs of the same problem and param (columns: 2 sweep_problem, 3 param, 4 budget, 7 refused, 9 error,
  # 10 cpu_per_sim_s), floored like the sweep's.
  if [ -r "$auto" ]; then
    awk -F, -v p="$p" -v v="$v" 'NR > 1 && $2 == p && $3 == v && $7 == 0 && $9 != "-" && $9 != "inf" {
      e = $9 + 0; if (e < 1e-9) e = 1e-9; c = $10 + 0; if (c < 1e-8) c = 1e-8; print c, e, $4 }' "$auto" > "$dir/auto"
    if [ -s "$dir/auto" ]; then
      plot+=", '$dir/auto' using 1:2 with points pt 9 ps 2.4 lc rgb 'red' title 'model: auto (label: budget)'"
      plot+=", '$dir/auto' using 1:2:3 with labels offset 2.2,0.6 tc rgb 'red' notitle"
    fi
  fi
  gnuplot <<GP
set terminal pngcairo size 900,600 font ',10'
set output '$out/$name.png'
set logscale xy
set format x '10^{%L}'
set format y '10^{%L}'
set grid
set key outside right top
set title "$name: error against cost (stable runs)"
set xlabel 'CPU seconds per simulated second'
set ylabel "$unit"
plot $plot
GP
  echo "plot-sweep: $out/$name.png"
  done
done

# Stability maps. tol: largest error still called "stable" (accurate).
stability_map() {  # problem(s) regex, output name, y label, tolerance, panel (3 = integrator, si = solver + iterations)
  local regex="$1" name="$2" ylabel="$3" tol="$4" col="$5"
  local dir="$work/map-$name"
  mkdir -p "$dir"
  awk -F, -v re="$regex" -v dir="$dir" -v tol="$tol" -v col="$col" '
    NR > 1 && $2 ~ re {
      panel = (col == "si") ? $8 "-" (NF >= 16 && $16 != "-" ? "sub" $16 : $6) : $col; f = dir "/" panel;
      if (!(panel in seen)) { seen[panel] = 1; order[++n] = panel }
      y = $9 + 0; if (y < 0) y = -y;
      cls = ($12 != 1 || $10 == "inf" || $10 == "nan") ? 2 : (($10 + 0) > tol ? 1 : 0);
      print $4, y, cls > f
    }
    END { for (i = 1; i <= n; i++) print order[i] > (dir "/panels") }' "$work/all.csv"
  [ -s "$dir/panels" ] || return 0
  local count; count=$(wc -l < "$dir/panels")
  local cols=$(( count < 3 ? count : 3 )); [ "$count" = 4 ] && cols=2
  local rows=$(( (count + cols - 1) / cols ))
  {
    echo "set terminal pngcairo size $((380 * cols)),$((330 * rows + 40)) font ',9'"
    echo "set output '$out/$name.png'"
    echo "set multiplot layout $rows,$cols title '$name: green stable, orange inaccurate (error > $tol), red unstable'"
    echo "set logscale xy; set format x '10^{%L}'; set format y '10^{%L}'; set grid; unset key"
    echo "set xlabel 'dt (s)'; set ylabel '$ylabel'; set xrange [5e-5:0.2]; set offsets 0,0,graph 0.05, graph 0.05"
    echo "set palette defined (0 '#2ca02c', 1 '#ff9f1a', 2 '#d62728'); set cbrange [0:2]; unset colorbox"
    while read -r panel; do
      local label="$panel"; [ "$col" = si ] && label="${panel%-*} solver, ${panel##*-} iterations"
      echo "set title '$label'"
      echo "plot '$dir/$panel' using 1:2:3 with points pt 5 ps 2.2 palette"
    done < "$dir/panels"
    echo "unset multiplot"
  } | gnuplot
  echo "plot-sweep: $out/$name.png"
}

stability_map '^spring-stiffness$' spring-stability 'stiffness K (N/m), 1 kg' 0.05 3
stability_map '^cloth(-stiffness)?$' cloth-stability '|book k| (x 33.3 N/m)' 0.25 3
stability_map '^stack-mass-ratio$' stack-stability 'top box mass ratio' 0.01 si

# "For this error, use this setting; it costs this much": per problem and target error, the cheapest stable run
# whose error is at or below the target (markdown, included by docs/sweep.md).
awk -F, -v maps=" $maps " '
  NR > 1 && $12 == 1 && $10 != "inf" && $10 != "nan" && index(maps, " " $2 " ") == 0 {
    s = ($3 != "-" ? $3 : ($8 != "-" ? $8 " solver" : "volumes")) " dt=" $4;
    if ($5 != "1") s = s " substeps=" $5;
    if ($6 != "-") s = s " iterations=" $6;
    if ($7 != "-") s = s " projection=" ($7 == "1" ? "on" : "off");
    if (NF >= 16 && $16 != "-") s = s " soft-substeps=" $16;
    label = $2; if ($9 != "-") label = label " (param " $9 ")";
    for (t = 1; t <= 3; t++) {
      target = 10 ^ -t; k = label SUBSEP target;
      if ($10 + 0 <= target && (!(k in cost) || $11 + 0 < cost[k])) { cost[k] = $11 + 0; set[k] = s; err[k] = $10 }
    }
    if (!(label in seen)) { seen[label] = 1; order[++n] = label }
  }
  END {
    print "| problem | target error | cheapest setting that meets it | error | CPU s per simulated s |";
    print "|---|---|---|---|---|";
    for (i = 1; i <= n; i++)
      for (t = 1; t <= 3; t++) {
        target = 10 ^ -t; k = order[i] SUBSEP target;
        if (k in cost) printf "| %s | %g | %s | %s | %.3g |\n", order[i], target, set[k], err[k], cost[k];
        else printf "| %s | %g | none in the sweep | | |\n", order[i], target;
      }
  }' "$work/all.csv" > "$out/cheapest.md"
echo "plot-sweep: $out/cheapest.md"
