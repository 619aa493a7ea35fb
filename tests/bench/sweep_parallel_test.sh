#!/bin/sh
# CI check of the ways to run the sweep's shards elsewhere: scripts/sweep-parallel.sh through GNU parallel
# (two local jobs, and the --sshloginfile path with the local machine ":" as its only host) and
# scripts/sweep.sbatch (its array tasks and dependent merge job run by hand, as Slurm would run them). Each
# merged CSV must equal the unsharded run in every column but the CPU-time measurement.
# Usage: sweep_parallel_test.sh REPO_ROOT PATH/TO/psb-sweep SCRATCH_DIR. Exit 77 (skipped) without GNU parallel.
set -eu
root=$1
sweep=$2
dir=$3
rm -rf "$dir" && mkdir -p "$dir"
fail() { echo "sweep.parallel: FAIL: $*" >&2; exit 1; }
if ! command -v parallel >/dev/null 2>&1; then
  echo "sweep.parallel: skipped: GNU parallel is not installed (Debian package 'parallel', scripts/install-deps.sh)"
  exit 77
fi
# A small grid over particle, spring, pendulum and contact problems (both contact solvers).
set -- --quick --problem projectile --problem spring-energy --problem pendulum-small --problem bounce-sphere \
       --problem incline --problem stack-5
"$sweep" "$@" --out "$dir/one.csv" 2>/dev/null || fail "unsharded psb-sweep exited $?"
strip() { awk -F, '{ $11 = ""; print }' OFS=, "$1"; }  # column 11 is CPU time, a measurement
strip "$dir/one.csv" >"$dir/one.rows"
[ "$(wc -l <"$dir/one.rows")" -gt 50 ] || fail "the unsharded run has too few rows"

bash "$root/scripts/sweep-parallel.sh" --jobs 2 --shards 3 --sweep "$sweep" --out "$dir/par.csv" -- "$@" \
  2>"$dir/par.err" || fail "sweep-parallel.sh exited $?: $(tail -n 3 "$dir/par.err")"
strip "$dir/par.csv" >"$dir/par.rows"
cmp -s "$dir/one.rows" "$dir/par.rows" || fail "GNU parallel's merged CSV differs from the unsharded run"
grep -q '^date: ' "$dir/par.csv.meta" && grep -q '^machine: ' "$dir/par.csv.meta" ||
  fail "sweep-parallel.sh wrote no par.csv.meta with the date and machine (scripts/gen-results.py --stamp)"

echo "2/:" >"$dir/hosts"
bash "$root/scripts/sweep-parallel.sh" --sshloginfile "$dir/hosts" --shards 2 --sweep "$sweep" --out "$dir/ssh.csv" \
  -- "$@" 2>"$dir/ssh.err" || fail "sweep-parallel.sh --sshloginfile exited $?: $(tail -n 3 "$dir/ssh.err")"
strip "$dir/ssh.csv" >"$dir/ssh.rows"
cmp -s "$dir/one.rows" "$dir/ssh.rows" || fail "the --sshloginfile run's merged CSV differs from the unsharded run"

# Slurm: two array tasks, then the merge job.
for i in 1 2; do
  (cd "$root" && PSB_SWEEP="$sweep" PSB_SWEEP_DIR="$dir/slurm" PSB_SWEEP_ARGS="$*" SLURM_ARRAY_TASK_ID=$i \
     SLURM_ARRAY_TASK_COUNT=2 bash scripts/sweep.sbatch) 2>/dev/null || fail "sweep.sbatch array task $i exited $?"
done
(cd "$root" && PSB_SWEEP_DIR="$dir/slurm" PSB_SWEEP_MERGE=2 bash scripts/sweep.sbatch) 2>/dev/null ||
  fail "sweep.sbatch merge job exited $?"
strip "$dir/slurm/results.csv" >"$dir/slurm.rows"
cmp -s "$dir/one.rows" "$dir/slurm.rows" || fail "the Slurm merge differs from the unsharded run"

# A failing shard: nothing written, non-zero exit.
if bash "$root/scripts/sweep-parallel.sh" --jobs 2 --sweep "$sweep" --out "$dir/bad.csv" -- --problem no-such \
  2>/dev/null; then fail "a failing shard did not fail the run"; fi
[ ! -e "$dir/bad.csv" ] || fail "a failing shard left $dir/bad.csv"
echo "sweep.parallel: ok ($(($(wc -l <"$dir/one.rows") - 1)) runs; GNU parallel, --sshloginfile and Slurm agree)"
