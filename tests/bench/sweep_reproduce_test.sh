#!/bin/sh
# The committed sweep results are what today's code computes: a fixed sample of docs/sweep/results.csv (up to
# three cheap runs of every problem, contact problems included) is run again with psb-sweep --runs, and its
# error and stable columns must equal the committed ones exactly (errors are deterministic; CPU time is a
# measurement and is not compared). A committed row is found in today's grid by its settings (problem .. param,
# through psb-sweep --plan), not by its run index, so points added to a grid (a new solver) do not move it. When physics changes on purpose, regenerate the results and figures
# (docs/sweep.md, "Reproducing these results") and this test passes again.
# Usage: sweep_reproduce_test.sh REPO_ROOT PATH/TO/psb-sweep SCRATCH_DIR
set -eu
root=$1
sweep=$2
dir=$3
rm -rf "$dir" && mkdir -p "$dir"
fail() { echo "sweep.reproduce: FAIL: $*" >&2; exit 1; }
committed="$root/docs/sweep/results.csv"
[ -r "$committed" ] || fail "no $committed"

# The sample: per problem, the runs costing at most 3,000 steps x solver passes, at most three of them spread
# over that list (first, middle, last). Columns: 1 run, 2 problem, 6 iterations, 10 error, 12 stable, 13 steps.
awk -F, 'NR > 1 {
    passes = ($6 == "-") ? 1 : $6 + 1
    if ($13 * passes <= 3000) { n[$2]++; run[$2, n[$2]] = $1 }
  }
  END {
    for (p in n) {
      k = n[p]; print run[p, 1]
      if (k >= 3) print run[p, int((k + 1) / 2)]
      if (k >= 2) print run[p, k]
    }
  }' "$committed" | sort -n -u >"$dir/runs"
count=$(wc -l <"$dir/runs")
problems=$(awk -F, 'NR > 1 {print $2}' "$committed" | sort -u | wc -l)
sampled=$(awk -F, 'NR == FNR { want[$1] = 1; next } FNR > 1 && ($1 in want) { print $2 }' "$dir/runs" "$committed" |
  sort -u | wc -l)
[ "$sampled" -eq "$problems" ] || fail "the sample covers $sampled of the $problems problems"
for p in stack-5 incline bounce-sphere; do
  awk -F, -v p="$p" 'NR == FNR { want[$1] = 1; next } FNR > 1 && ($1 in want) && $2 == p { found = 1 }
    END { exit !found }' "$dir/runs" "$committed" || fail "the sample has no $p run"
done

# Settings key: columns 2..9 (problem, integrator, dt, substeps, iterations, projection, solver, param) and 16..25
# (the soft solver's settings, which tell its substep counts apart; "-" on other rows).
key='$2 "," $3 "," $4 "," $5 "," $6 "," $7 "," $8 "," $9 "," $16 "," $17 "," $18 "," $19 "," $20 "," $21 "," $22 "," $23 "," $24 "," $25'
awk -F, "NR == FNR { want[\$1] = 1; next } FNR > 1 && (\$1 in want) { print $key \",\" \$10 \",\" \$12 }" \
  "$dir/runs" "$committed" | sort >"$dir/committed.rows"
"$sweep" --plan >"$dir/plan.csv" 2>"$dir/plan.err" || fail "psb-sweep --plan exited $?: $(tail -n 2 "$dir/plan.err")"
awk -F, "NR == FNR { k = \$0; sub(/,[^,]*,[^,]*\$/, \"\", k); want[k] = 1; next }
  FNR > 1 && (($key) in want) { print \$1 }" "$dir/committed.rows" "$dir/plan.csv" | sort -n >"$dir/today.runs"
[ "$(wc -l <"$dir/today.runs")" -eq "$count" ] ||
  fail "$(wc -l <"$dir/today.runs") of the $count sampled settings are in today's grid (psb-sweep --plan)"
"$sweep" --runs "$(paste -sd, "$dir/today.runs")" --out "$dir/now.csv" 2>"$dir/now.err" ||
  fail "psb-sweep --runs exited $?: $(tail -n 2 "$dir/now.err")"
awk -F, "FNR > 1 { print $key \",\" \$10 \",\" \$12 }" "$dir/now.csv" | sort >"$dir/now.rows"
[ "$(wc -l <"$dir/now.rows")" -eq "$count" ] || fail "psb-sweep ran $(wc -l <"$dir/now.rows") of $count runs"
if ! cmp -s "$dir/committed.rows" "$dir/now.rows"; then
  diff "$dir/committed.rows" "$dir/now.rows" | head -n 20 >&2
  fail "today's code computes other errors than docs/sweep/results.csv (settings,error,stable: < committed, > now)"
fi
echo "sweep.reproduce: ok ($count committed runs of $problems problems reproduced exactly)"
