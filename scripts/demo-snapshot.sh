#!/usr/bin/env bash
# Writes, for every demo, the golden frames (the run.args of tests/golden/<id>/) and the default --state CSV
# (300 frames, panels off) into OUTDIR, plus OUTDIR/SHA256SUMS. A refactor proves itself by giving the same
# SHA256SUMS before and after:  scripts/demo-snapshot.sh build /tmp/before ... scripts/demo-snapshot.sh build
# /tmp/after && diff /tmp/before/SHA256SUMS /tmp/after/SHA256SUMS
set -euo pipefail
[ $# -eq 2 ] || { echo "usage: $0 BUILD_DIR OUTDIR" >&2; exit 2; }
root=$(cd "$(dirname "$0")/.." && pwd)
exe=$1/physics-sandbox
out=$2
[ -x "$exe" ] || { echo "demo-snapshot: no executable at $exe" >&2; exit 2; }
mkdir -p "$out"
for id in $("$exe" --list | cut -f1); do
  mapfile -t args < "$root/tests/golden/$id/run.args"
  "$exe" --demo "$id" "${args[@]}" --out "$out/$id" --quiet
  "$exe" --demo "$id" --frames 300 --no-ui --state "$out/$id.csv" --quiet
done
(cd "$out" && find . -type f ! -name SHA256SUMS | sort | xargs sha256sum > SHA256SUMS)
echo "demo-snapshot: $(wc -l < "$out/SHA256SUMS") files in $out"
