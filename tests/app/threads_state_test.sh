#!/bin/sh
# --threads 1, 2 and 3 write the same --state CSV, byte for byte (docs/threads.md); and a bad --threads is refused
# with a message naming the value. Usage: threads_state_test.sh EXE OUTDIR ARGS... (ARGS: the run, e.g. --scene F).
exe=$1
out=$2
shift 2
rm -rf "$out"
mkdir -p "$out" || exit 1
for t in 1 2 3; do
  if ! "$exe" "$@" --threads $t --state "$out/threads-$t.csv" --quiet; then
    echo "threads_state: --threads $t failed: $*"
    exit 1
  fi
done
if [ ! -s "$out/threads-1.csv" ]; then
  echo "threads_state: --threads 1 wrote no state"
  exit 1
fi
for t in 2 3; do
  if ! cmp "$out/threads-1.csv" "$out/threads-$t.csv"; then
    echo "threads_state: --threads $t differs from --threads 1: $*"
    exit 1
  fi
done
for bad in 0 257 two; do
  "$exe" "$@" --threads $bad --state "$out/bad.csv" --quiet 2>"$out/bad.txt"
  code=$?
  if [ $code -ne 2 ] || ! grep -q -- "--threads $bad" "$out/bad.txt" || [ -e "$out/bad.csv" ]; then
    echo "threads_state: --threads $bad: exit $code (want 2), message: $(cat "$out/bad.txt")"
    exit 1
  fi
done
echo "threads_state: the same $(wc -l <"$out/threads-1.csv") rows on 1, 2 and 3 threads: $*"
