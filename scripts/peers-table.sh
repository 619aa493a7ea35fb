#!/usr/bin/env bash
# Measures the peer table (docs/results.md, "Speed against Bullet"): every peer scene with the soft solver, sleeping
# off and on in both engines, one thread, through `psb-peer-bench --csv`; writes docs/data/peers.csv (whole or not at
# all) and its date/machine sidecar, then regenerates docs/results.md and the README's results table.
#   scripts/peers-table.sh [BUILD_DIR]        (default build; about 3 minutes on 2 cores; run it on an idle machine)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bench=${1:-$root/build}/psb-peer-bench
[ -x "$bench" ] || { echo "peers-table: no psb-peer-bench at $bench" >&2; exit 2; }
scenes=("boxpile 100" "boxpile 1000" "boxpile 4000" "pyramid 10" "pyramid 20" "pyramid 30" "tower 10" "tower 20")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
out="$tmp/peers.csv"
for sleep in "" "--sleep"; do
  for s in "${scenes[@]}"; do
    read -r scene n <<< "$s"
    echo "peers-table: $scene $n ${sleep:---no-sleep}" >&2
    # shellcheck disable=SC2086
    "$bench" "$scene" "$n" --solver soft $sleep --csv "$tmp/one.csv" > /dev/null
    if [ -f "$out" ]; then tail -n +2 "$tmp/one.csv" >> "$out"; else cp "$tmp/one.csv" "$out"; fi
  done
done
mkdir -p "$root/docs/data"
mv "$out" "$root/docs/data/peers.csv"
python3 "$root/scripts/gen-results.py" --stamp "$root/docs/data/peers.csv" \
  --command "scripts/peers-table.sh (psb-peer-bench SCENE N --solver soft [--sleep] --csv)"
python3 "$root/scripts/gen-results.py" --root "$root"
echo "peers-table: docs/data/peers.csv ($(($(wc -l < "$root/docs/data/peers.csv") - 1)) rows), docs/results.md" >&2
