#!/bin/sh
# scripts/gen-results.py reads the peer bench's CSV when it exists and says "not measured yet" when it does not.
# The rows below are made up by this test in its own temporary folder; nothing here is a measurement.
# usage: results_peers_test.sh REPO PYTHON WORKDIR
set -eu
repo=$1 py=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
cat > "$work/peers.csv" <<'CSV'
scene,bodies,sleep,threads,engine,cpu_ms_per_step,ratio_to_bullet,max_displacement_m,stands
tower,17,off,1,bullet,0.0123456,1,0.5,0
tower,17,off,1,psb-soft,0.00617,0.5,0.00281,1
CSV
"$py" "$repo/scripts/gen-results.py" --stamp "$work/peers.csv" --command "test rows" --date "test date" \
  --machine "test machine"
"$py" "$repo/scripts/gen-results.py" --root "$repo" --peers "$work/peers.csv" --out "$work/with.md"
grep -q '^| tower | 17 | off | 1 | bullet | 0.0123 | 1 | 0.5 | no |$' "$work/with.md" || { echo "no bullet row"; exit 1; }
grep -q '^| tower | 17 | off | 1 | psb-soft | 0.00617 | 0.5 | 0.00281 | yes |$' "$work/with.md" || { echo "no soft row"; exit 1; }
grep -q 'measured test date, on test machine' "$work/with.md" || { echo "no provenance line"; exit 1; }
"$py" "$repo/scripts/gen-results.py" --root "$repo" --peers "$work/absent.csv" --out "$work/without.md"
grep -q 'Not measured yet: `docs/data/peers.csv` does not exist.' "$work/without.md" || { echo "no 'not measured'"; exit 1; }
echo "results_peers_test: ok"
