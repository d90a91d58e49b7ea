#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Builds the libFuzzer harnesses (clang, ASan + UBSan in build-fuzz/; the rawlog guard's
# harness UBSan only, in build-fuzz-guard/) and runs each one.
#   scripts/fuzz.sh                 each harness for 10^6 inputs
#   RUNS=20000 scripts/fuzz.sh      a short fixed budget (what the ctest fuzz_parsers runs)
#   BUILD_DIR=DIR scripts/fuzz.sh   build the harnesses in DIR instead of build-fuzz/
#   SECONDS_EACH=3600 scripts/fuzz.sh   each for an hour instead of a count
# New inputs go to out/fuzz/<harness>/ (the seed corpora in tests/fuzz/corpus stay as they
# are); a crash leaves out/fuzz/<harness>/crash-* and a non-zero exit.
set -euo pipefail
cd "$(dirname "$0")/.."
RUNS=${RUNS:-1000000}
JOBS=${JOBS:-2}
BUILD=${BUILD_DIR:-build-fuzz}
launcher=()
command -v ccache > /dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
configure() {  # build folder, sanitizers
  cmake -S . -B "$1" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ -DLOOKAHEAD_FUZZ=ON \
    -DLOOKAHEAD_FUZZ_SANITIZERS="$2" -DLOOKAHEAD_BUILD_TESTS=OFF -DLOOKAHEAD_BUILD_BENCH=OFF "${launcher[@]}" >/dev/null
}
# The rawlog harness reads through the guard, whose child limits its address space: it is
# built with UBSan only, in its own folder (cmake/Sanitizers.cmake says why). Ask for it by
# name: HARNESSES="rawlog_reader" scripts/fuzz.sh
read -r -a harnesses <<< "${HARNESSES:-carmen_reader map_loader stage_world config_yaml}"
build_of() { [ "$1" = rawlog_reader ] && echo "$BUILD-guard" || echo "$BUILD"; }
asan=() guard=()
for h in "${harnesses[@]}"; do
  if [ "$h" = rawlog_reader ]; then guard+=("fuzz_$h"); else asan+=("fuzz_$h"); fi
done
if [ ${#asan[@]} -gt 0 ]; then configure "$BUILD" address,undefined && cmake --build "$BUILD" -j"$JOBS" --target "${asan[@]}"; fi
if [ ${#guard[@]} -gt 0 ]; then configure "$BUILD-guard" undefined && cmake --build "$BUILD-guard" -j"$JOBS" --target "${guard[@]}"; fi
status=0
for h in "${harnesses[@]}"; do
  corpus=tests/fuzz/corpus/$(echo "$h" | sed -E 's/_reader|_loader//')
  work=out/fuzz/$h
  mkdir -p "$work"
  limit=(-runs="$RUNS")
  [ -n "${SECONDS_EACH:-}" ] && limit=(-max_total_time="$SECONDS_EACH")
  start=$(date +%s)
  bin_dir=$(realpath "$(build_of "$h")")/tests/fuzz
  if ! (cd "$work" && "$bin_dir/fuzz_$h" "${limit[@]}" -seed=1 -rss_limit_mb=2048 \
        -timeout=20 -print_final_stats=1 . "$OLDPWD/$corpus" >log.txt 2>&1); then
    status=1
    echo "fuzz_$h: FAILED, see $work/log.txt"
  elif grep -q '^SUMMARY: [A-Za-z]*Sanitizer' "$work/log.txt"; then
    # The rawlog guard's child dies of a finding without ending the run: its report is in the
    # log (the child's crash-* file holds the input it was forked with, not the one it read).
    status=1
    echo "fuzz_$h: FAILED, a sanitizer finding in the guarded child, see $work/log.txt"
  fi
  runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$work/log.txt" | grep -o '[0-9]*$' || echo "?")
  echo "fuzz_$h: $runs inputs in $(( $(date +%s) - start )) s"
done
exit $status
