#!/usr/bin/env bash
# Builds the libFuzzer targets of tests/fuzz with clang (a tree of its own, build-fuzz/, configured with
# -DPSB_FUZZ=ON: coverage + ASan + UBSan) and runs each for a fixed time, starting from a copy of its
# committed corpus (tests/fuzz/corpus/<target>/) and its regressions, so the committed corpus never grows.
# Exit 1 if any target finds a crash, leak, timeout, out-of-memory or failed check; its inputs are kept in
# build-fuzz/findings/<target>/. Usage: scripts/fuzz.sh [seconds per target, default 60] [target...]
# docs/testing.md "Fuzzing" says how a finding becomes a regression test.
set -euo pipefail
cd "$(dirname "$0")/.."

seconds=${1:-60}
shift || true
build=${PSB_FUZZ_BUILD:-build-fuzz}
jobs=$(nproc 2>/dev/null || echo 2)

cmake -S . -B "$build" -DPSB_FUZZ=ON -DPSB_WERROR=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ >/dev/null
cmake --build "$build" -j"$jobs" --target psb_fuzz

targets=("$@")
if [ ${#targets[@]} -eq 0 ]; then
  for dir in tests/fuzz/corpus/*/; do targets+=("$(basename "$dir")"); done
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failed=()
for t in "${targets[@]}"; do
  [ -x "$build/$t" ] || { echo "fuzz: no target $t in $build" >&2; exit 2; }
  findings="$build/findings/$t"
  rm -rf "$findings"
  mkdir -p "$work/$t" "$findings"
  cp -R "tests/fuzz/corpus/$t/." "$work/$t/"
  inputs=("$work/$t")
  [ -d "tests/fuzz/regressions/$t" ] && inputs+=("tests/fuzz/regressions/$t")
  echo "== fuzz $t for ${seconds}s"
  if ! "$build/$t" "${inputs[@]}" -max_total_time="$seconds" -rss_limit_mb=2048 -timeout=10 \
       -print_final_stats=1 -artifact_prefix="$findings/" >"$findings/log.txt" 2>&1; then
    failed+=("$t")
    grep -E 'ERROR|SUMMARY|check failed|Test unit written' "$findings/log.txt" | head -20 >&2 || true
    echo "fuzz: $t FAILED; log and inputs in $findings/" >&2
  fi
  grep -E '^stat::number_of_executed_units|^Done' "$findings/log.txt" || true
done

if [ ${#failed[@]} -ne 0 ]; then
  echo "fuzz: findings in ${failed[*]} (see docs/testing.md \"Fuzzing\")" >&2
  exit 1
fi
echo "fuzz: ${#targets[@]} targets, ${seconds}s each, nothing found"
