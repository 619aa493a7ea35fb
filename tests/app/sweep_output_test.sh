#!/bin/sh
# psb-sweep's output is written whole or not at all (docs/sweep.md): a write that fails (here the file-size
# limit, standing in for a full disk) ends the run at once with exit 3, a message naming the path and the system
# error, and leaves neither the CSV nor a temporary. Usage: sweep_output_test.sh PATH/TO/psb-sweep SCRATCH_DIR
set -u
sweep=$1
dir=$2
rm -rf "$dir" && mkdir -p "$dir"
fail() { echo "sweep.output: FAIL: $*" >&2; exit 1; }

# stderr goes to a pipe: under the limit a write to any regular file fails, the message's too.
out=$( (ulimit -f 0; exec "$sweep" --quick --problem projectile --out "$dir/q.csv") 2>&1 >/dev/null; echo "rc=$?")
case "$out" in *"rc=3") ;; *) fail "write failure: expected exit 3, got: $out" ;; esac
case "$out" in *"$dir/q.csv"*) ;; *) fail "message does not name the path: $out" ;; esac
case "$out" in *"File too large"*) ;; *) fail "message does not give the system error: $out" ;; esac
[ -z "$(ls -A "$dir")" ] || fail "left files behind: $(ls -A "$dir")"

# An unwritable directory is refused before any run is computed.
"$sweep" --quick --problem projectile --out "$dir/no/such/dir/q.csv" 2>"$dir/err"; rc=$?
[ "$rc" -eq 3 ] || fail "missing directory exited $rc, expected 3"
grep -q '^\[1/' "$dir/err" && fail "runs were computed before the output was opened"

# A successful run leaves exactly the CSV.
"$sweep" --quick --problem projectile --out "$dir/ok.csv" 2>/dev/null || fail "plain run exited $?"
[ "$(ls -A "$dir" | grep -v '^err$')" = "ok.csv" ] || fail "unexpected files: $(ls -A "$dir")"
echo "sweep.output: ok"
