#!/usr/bin/env bash
# Merges psb-sweep shard CSVs into one CSV: one header, rows sorted by run, no run twice. The result is what
# one unsharded psb-sweep run with the same arguments writes (timing columns aside). An input may hold several
# shards one after another (each with its header, as GNU parallel returns them); every header must be the
# same. Written to a temporary file beside OUT and renamed, so OUT is whole or absent.
# Usage: scripts/sweep-merge.sh OUT SHARD.csv... ; exit 2 on bad usage, 1 if the shards do not fit together.
set -euo pipefail
[ $# -ge 2 ] || { echo "usage: $0 OUT SHARD.csv..." >&2; exit 2; }
out=$1; shift
header=
for f in "$@"; do
  [ -f "$f" ] || { echo "sweep-merge: no shard file '$f'" >&2; exit 2; }
  h=$(head -n 1 "$f")
  [ "${h%%,*}" = run ] || { echo "sweep-merge: '$f' does not start with the psb-sweep header" >&2; exit 1; }
  [ -z "$header" ] || [ "$h" = "$header" ] || { echo "sweep-merge: '$f' has another header than '$1'" >&2; exit 1; }
  header=$h
done
tmp=$(mktemp "$(dirname -- "$out")/.sweep-merge.XXXXXX")
trap 'rm -f "$tmp"' EXIT
other=$(cat "$@" | grep '^run,' | grep -vxF -- "$header" | head -n 1 || true)
[ -z "$other" ] || { echo "sweep-merge: a shard has another header: $other" >&2; exit 1; }
{ printf '%s\n' "$header"; cat "$@" | grep -v '^run,' | sort -t, -k1,1n; } >"$tmp"
dups=$(tail -n +2 "$tmp" | cut -d, -f1 | uniq -d | head -n 3 | tr '\n' ' ')
[ -z "$dups" ] || { echo "sweep-merge: runs in more than one shard: $dups" >&2; exit 1; }
chmod 644 "$tmp"
mv -f "$tmp" "$out"
trap - EXIT
echo "sweep-merge: $(($(wc -l <"$out") - 1)) runs -> $out" >&2
