#!/bin/sh
# CI check of psb-model-choice-bench (docs/model-choice-validation.md): the reference scene files are valid and are
# the sweep's problems (--check: the same error as the sweep's own run at the same settings), and on the small grid
# `model: auto` stays within 3x every budget it accepts and refuses only budgets no sweep setting meets. Timings
# are not checked (they are the full bench's report, never a test).
# Usage: model_choice_test.sh SOURCE_DIR PATH/TO/psb-model-choice-bench SCRATCH_DIR
set -eu
src=$1
bench=$2
dir=$3
rm -rf "$dir" && mkdir -p "$dir/scenes"
fail() { echo "model_choice.quick: FAIL: $*" >&2; exit 1; }

# The reference scenes against the scene schema (the checker reads DIR/scenes/*.json).
if command -v python3 >/dev/null 2>&1; then
  cp "$src/scenes/scene.schema.json" "$src"/scenes/reference/*.json "$dir/scenes/"
  python3 "$src/scripts/check-scenes.py" "$dir" >"$dir/schema.out" 2>&1 || { cat "$dir/schema.out" >&2; fail "schema"; }
fi

# Every scene file gives its sweep problem's error, bit for bit up to 1e-9 (its volumes carry the sweep's
# velocityEpsilon 0).
"$bench" --check >"$dir/check.md" 2>"$dir/check.err" || { cat "$dir/check.md" "$dir/check.err" >&2; fail "--check exited $?"; }
[ "$(grep -c '^| [a-z]' "$dir/check.md")" -ge 29 ] || fail "--check compared fewer than 29 settings"

# The small grid: auto within 3x the budget wherever it runs; a refusal only where the sweep has no setting either.
# Without the choice's CPU limit (--cpu-limit 0), so the outcome does not depend on the machine's speed or load.
"$bench" --quick --cpu-limit 0 --csv "$dir/quick.csv" --out "$dir/quick.md" >/dev/null 2>"$dir/quick.err" ||
  { cat "$dir/quick.err" >&2; fail "--quick exited $?"; }
header='problem,sweep_problem,param,budget,quantity,auto_bound,refused,model,error,cpu_per_sim_s,overhead_cpu_s,switches,cheapest,cheapest_error,cheapest_cpu_per_sim_s,cost_ratio,own_quantity,margin,margin_error,margin_cpu_per_sim_s'
[ "$(head -n 1 "$dir/quick.csv")" = "$header" ] || fail "unexpected CSV header: $(head -n 1 "$dir/quick.csv")"
[ "$(($(wc -l <"$dir/quick.csv") - 1))" -ge 6 ] || fail "fewer than 6 cases in the small grid"
# A refusal where a sweep setting meets the budget is allowed only when auto found the candidates it would choose
# unreliable (their error did not shrink with the step at the order assumed: the sweep's setting met it by chance,
# as the e = 0.9 sphere's bounce timings at 1e-2 do), and its message says so.
awk -F, 'NR > 1 {
    if (NF != 20) { print "row " NR " has " NF " columns, not 20"; bad = 1 }
    if ($7 == 1) { if ($13 != "-") print $1 " budget " $4 ": auto refused" > "'"$dir/refused-with-sweep.txt"'" }
    else if ($9 == "-" || $9 + 0 > 3 * $4) { print $1 " at " $4 ": auto error " $9 " is above 3x the budget (" $8 ")"; bad = 1 }
  } END { exit bad }' "$dir/quick.csv" || fail "accuracy above"
if [ -f "$dir/refused-with-sweep.txt" ]; then
  while IFS= read -r line; do
    grep -F "$line" "$dir/quick.err" | grep -q 'did not shrink with the step' ||
      fail "$line, though the sweep meets it, and not for unreliable candidates: $(grep -F "$line" "$dir/quick.err")"
  done <"$dir/refused-with-sweep.txt"
fi
grep -q 'within budget:' "$dir/quick.md" || fail "the report has no criteria"

# Outside --quick each case also runs the cheapest sweep setting meeting the budget over the safety factor (2): its
# error, re-measured here, is within half the budget (spring-phase at 0.1: the cheapest meeting 0.1 is 0.07 off).
"$bench" --problem spring-phase --cpu-limit 0 --csv "$dir/margin.csv" >/dev/null 2>"$dir/margin.err" ||
  { cat "$dir/margin.err" >&2; fail "--problem spring-phase exited $?"; }
awk -F, 'NR > 1 {
    if ($18 == "-" || $19 == "-") { print $1 " at " $4 ": no margin setting"; bad = 1 }
    else if ($19 + 0 > $4 / 2) { print $1 " at " $4 ": margin " $18 " is " $19 " off, above half the budget"; bad = 1 }
  } END { exit bad }' "$dir/margin.csv" || fail "margin settings above"

# --safety reaches auto: its explanation states the factor it chose with.
"$bench" --problem projectile --budgets 0.1 --safety 1.5 --explain >/dev/null 2>"$dir/safety.err" ||
  { cat "$dir/safety.err" >&2; fail "--safety 1.5 exited $?"; }
grep -q 'safety factor 1.5;' "$dir/safety.err" || fail "--safety 1.5 did not reach auto: $(grep -m1 'safety factor' "$dir/safety.err")"

# Bad usage is refused with exit 2.
set +e
"$bench" --safety 0.5 >/dev/null 2>&1; [ $? -eq 2 ] || fail "--safety 0.5 not refused with exit 2"
"$bench" --safety nan >/dev/null 2>&1; [ $? -eq 2 ] || fail "--safety nan not refused with exit 2"
"$bench" --cpu-limit -1 >/dev/null 2>&1; [ $? -eq 2 ] || fail "--cpu-limit -1 not refused with exit 2"
"$bench" --budgets 0,-1 >/dev/null 2>&1; [ $? -eq 2 ] || fail "--budgets 0,-1 not refused with exit 2"
"$bench" --problem nonesuch >/dev/null 2>&1; [ $? -eq 2 ] || fail "--problem nonesuch not refused with exit 2"
exit 0
