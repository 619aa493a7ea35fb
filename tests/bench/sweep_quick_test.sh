#!/bin/sh
# CI check of the speed-accuracy sweep tool on its small grid: it runs, covers every default
# problem, its numbers show what the physics must show, sharding splits without losing or changing runs,
# and bad input is refused. Usage: sweep_quick_test.sh PATH/TO/psb-sweep SCRATCH_DIR
set -eu
sweep=$1
dir=$2
rm -rf "$dir" && mkdir -p "$dir"
fail() { echo "sweep.quick: FAIL: $*" >&2; exit 1; }

"$sweep" --quick --out "$dir/all.csv" 2>"$dir/all.err" || fail "psb-sweep --quick exited $?"
header='run,problem,integrator,dt,substeps,iterations,projection,solver,param,error,cpu_per_sim_s,stable,steps,sim_s,note,soft_substeps,soft_iterations,soft_relax_iterations,soft_contact_hertz,soft_contact_damping_ratio,soft_max_pushout_speed,soft_speculative_margin,soft_linear_slop,soft_restitution_threshold,soft_warm_start_factor'
[ "$(head -n 1 "$dir/all.csv")" = "$header" ] || fail "unexpected CSV header: $(head -n 1 "$dir/all.csv")"

# Every problem of the default set has rows, except cloth-stiffness: each of its stiffnesses needs its own
# converged small-step reference, too slow for CI, so the tool gives it no quick grid on purpose.
"$sweep" --list >"$dir/list.txt" || fail "--list exited $?"
[ "$(wc -l <"$dir/list.txt")" -ge 15 ] || fail "--list names fewer than 15 problems"
for p in $(awk '!/not in the default set/ && $1 != "cloth-stiffness" {print $1}' "$dir/list.txt"); do
  grep -q "^[0-9]*,$p," "$dir/all.csv" || fail "no rows for default problem '$p'"
done

# Physics the rows must show (columns: 2 problem, 3 integrator, 4 dt, 10 error, 12 stable).
awk -F, '
  $2 == "projectile" && $3 == "explicit-euler" { ee[$4] = $10 }
  $2 == "projectile" && $3 == "velocity-verlet" && $10 + 0 > 1e-3 { print "velocity Verlet projectile error " $10 " at dt " $4 " (exact under constant force)"; bad = 1 }
  $2 == "spring-energy" && $3 == "explicit-euler" && $12 == 1 { print "explicit Euler spring energy run at dt " $4 " not flagged unstable"; bad = 1 }
  $2 == "spring-energy" && ($3 == "verlet" || $3 == "velocity-verlet") && $12 != 1 { print "symplectic " $3 " spring energy run at dt " $4 " flagged unstable"; bad = 1 }
  END {
    if (!("0.001" in ee) || !("0.01" in ee)) { print "explicit Euler projectile rows at dt 0.001 and 0.01 missing"; exit 1 }
    r = ee["0.01"] / ee["0.001"]
    if (r < 8 || r > 12) { print "explicit Euler projectile error ratio for 10x dt is " r ", first order needs ~10"; bad = 1 }
    exit bad
  }' "$dir/all.csv" || fail "physics checks above"

# The contact problems run the soft solver at its own substep count, recorded with its settings so a row can be
# re-run; other rows leave the soft columns '-' (columns 6 iterations, 8 solver, 16 soft_substeps, 25 the last).
awk -F, '
  NR > 1 && NF != 25 { print "row " $1 " has " NF " columns, not 25"; bad = 1 }
  NR > 1 && $8 == "soft" { soft[$2]++; if ($6 != "-" || $16 !~ /^[0-9]+$/ || $25 == "-") { print "soft row " $1 " lacks its settings"; bad = 1 } }
  NR > 1 && $8 != "soft" && $16 != "-" { print "row " $1 " (" $8 ") has soft settings"; bad = 1 }
  END {
    n = split("bounce-sphere incline stack-5 stack-10 stack-mass-ratio", p, " ")
    for (i = 1; i <= n; i++) if (!(p[i] in soft)) { print "no soft rows for " p[i]; bad = 1 }
    exit bad
  }' "$dir/all.csv" || fail "soft solver rows above"

# Two shards together are exactly the unsharded runs (CPU time column excluded: it is a measurement).
for i in 1 2; do
  "$sweep" --quick --problem projectile --problem spring-energy --shard "$i/2" --out "$dir/s$i.csv" 2>/dev/null ||
    fail "--shard $i/2 exited $?"
done
strip() { awk -F, 'FNR > 1 { $11 = ""; print }' OFS=, "$@" | sort -t, -k1,1n; }
"$sweep" --quick --problem projectile --problem spring-energy --out "$dir/two.csv" 2>/dev/null || fail "subset run exited $?"
strip "$dir/two.csv" >"$dir/two.rows"
strip "$dir/s1.csv" "$dir/s2.csv" >"$dir/shards.rows"
[ -s "$dir/two.rows" ] || fail "subset run produced no rows"
cmp -s "$dir/two.rows" "$dir/shards.rows" || fail "shards 1/2 + 2/2 differ from the unsharded run"
[ "$(wc -l <"$dir/s1.csv")" -gt 1 ] && [ "$(wc -l <"$dir/s2.csv")" -gt 1 ] || fail "a shard is empty"

# Bad input: exit 2, message names the value, nothing written.
set +e
"$sweep" --shard 3/2 --out "$dir/bad.csv" 2>"$dir/bad.err"; rc=$?
set -e
[ "$rc" -eq 2 ] || fail "--shard 3/2 exited $rc, expected 2"
grep -q "3/2" "$dir/bad.err" || fail "error message does not name '3/2': $(cat "$dir/bad.err")"
[ ! -e "$dir/bad.csv" ] || fail "--shard 3/2 left $dir/bad.csv behind"
echo "sweep.quick: ok ($(($(wc -l <"$dir/all.csv") - 1)) runs)"
