#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Builds the unit tests with AddressSanitizer + UndefinedBehaviorSanitizer (build-sanitize/,
# GCC, the compiler of the main build) and runs every unit test binary. Any finding fails
# the run: UBSan is built with -fno-sanitize-recover.
set -euo pipefail
cd "$(dirname "$0")/.."
JOBS=${JOBS:-2}
cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=RelWithDebInfo -DLOOKAHEAD_SANITIZE=ON \
  -DLOOKAHEAD_BUILD_BENCH=OFF -DCMAKE_CXX_COMPILER_LAUNCHER=ccache >/dev/null
tests=(lookahead_unit_tests lookahead_planner_tests lookahead_predictor_tests lookahead_exploration_tests)
cmake --build build-sanitize -j"$JOBS" --target "${tests[@]}"
# detect_leaks: the tests own what they allocate; a leak in a parser is a finding too.
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
for t in "${tests[@]}"; do
  bin=$(find build-sanitize -type f -name "$t" -perm -u+x | head -1)
  echo "== $t"
  "$bin" --gtest_brief=1
done
