#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Builds the unit tests with AddressSanitizer + UndefinedBehaviorSanitizer (GCC, the compiler
# of the main build) and runs them. Any finding fails the run: UBSan is built with
# -fno-sanitize-recover and LeakSanitizer is on.
#   scripts/sanitize.sh                  all four unit-test binaries, every test (build-sanitize/)
#   BUILD_DIR=DIR scripts/sanitize.sh    build in DIR instead of build-sanitize/
#   TESTS="lookahead_unit_tests" scripts/sanitize.sh    only these binaries
#   GTEST_FILTER='CarmenReader*' scripts/sanitize.sh    only these tests of each binary
set -euo pipefail
cd "$(dirname "$0")/.."
JOBS=${JOBS:-2}
BUILD=${BUILD_DIR:-build-sanitize}
launcher=()
command -v ccache > /dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DLOOKAHEAD_SANITIZE=ON \
  -DLOOKAHEAD_BUILD_BENCH=OFF "${launcher[@]}" >/dev/null
read -r -a tests <<< "${TESTS:-lookahead_unit_tests lookahead_planner_tests lookahead_predictor_tests lookahead_exploration_tests}"
start=$(date +%s)
cmake --build "$BUILD" -j"$JOBS" --target "${tests[@]}"
echo "== built in $(( $(date +%s) - start )) s"
# detect_leaks: the tests own what they allocate; a leak in a parser is a finding too.
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
for t in "${tests[@]}"; do
  bin=$(find "$BUILD" -type f -name "$t" -perm -u+x | head -1)
  echo "== $t"
  start=$(date +%s)
  "$bin" --gtest_brief=1 --gtest_filter="${GTEST_FILTER:-*}"
  echo "== $t: passed in $(( $(date +%s) - start )) s"
done
