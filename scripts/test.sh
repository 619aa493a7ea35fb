#!/usr/bin/env bash
# Builds and runs every test: installs dependencies (Debian 12 packages), a Release build with warnings as
# errors and the full CTest suite (unit, physics, app, golden frames), then an AddressSanitizer +
# UndefinedBehaviorSanitizer build running the same suite, then the libFuzzer targets for a fixed time
# (scripts/fuzz.sh, docs/testing.md). This is the README's test command and what CI runs.
set -euo pipefail
cd "$(dirname "$0")/.."

jobs=$(nproc 2>/dev/null || echo 2)
step() { printf '\n== %s\n' "$*"; }

step "dependencies"
bash scripts/install-deps.sh

step "release build"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DPSB_WERROR=ON
cmake --build build -j"$jobs"

step "tests (release)"
ctest --test-dir build --output-on-failure -j"$jobs"

if [ "${PSB_SKIP_SANITIZERS:-0}" != "1" ]; then
  step "sanitizer build (ASan + UBSan)"
  # The benchmarks stay out (timings mean nothing under sanitizers); psb-sweep and its CTests (sweep.quick,
  # sweep.output) are built and run, so its problems and its output path are checked too.
  cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPSB_SANITIZE=ON -DPSB_WERROR=ON -DPSB_BUILD_BENCH=OFF \
    -DPSB_BUILD_SWEEP=ON
  cmake --build build-asan -j"$jobs"
  step "tests (ASan + UBSan)"
  # Mesa's llvmpipe is not instrumented; its one-time allocations are not leaks of ours.
  ASAN_OPTIONS="detect_leaks=1:abort_on_error=1" \
  LSAN_OPTIONS="suppressions=$PWD/scripts/lsan.supp" \
  UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1" \
    ctest --test-dir build-asan --output-on-failure -j"$jobs"
fi

if [ "${PSB_SKIP_FUZZ:-0}" != "1" ]; then
  step "fuzzing (libFuzzer, ${PSB_FUZZ_SECONDS:-60} s a target)"
  bash scripts/fuzz.sh "${PSB_FUZZ_SECONDS:-60}"
fi
