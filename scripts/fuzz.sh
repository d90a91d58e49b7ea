#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Builds the libFuzzer harnesses (clang, ASan + UBSan; build-fuzz/) and runs each one.
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
cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
  -DLOOKAHEAD_FUZZ=ON -DLOOKAHEAD_BUILD_TESTS=OFF -DLOOKAHEAD_BUILD_BENCH=OFF "${launcher[@]}" >/dev/null
# The rawlog harness forks a guarded child per input (about 6 inputs/s): ask for it by name,
#   HARNESSES="rawlog_reader" SECONDS_EACH=600 scripts/fuzz.sh
read -r -a harnesses <<< "${HARNESSES:-carmen_reader map_loader stage_world config_yaml}"
cmake --build "$BUILD" -j"$JOBS" --target "${harnesses[@]/#/fuzz_}"
bin_dir=$(realpath "$BUILD")/tests/fuzz
status=0
for h in "${harnesses[@]}"; do
  corpus=tests/fuzz/corpus/$(echo "$h" | sed -E 's/_reader|_loader//')
  work=out/fuzz/$h
  mkdir -p "$work"
  limit=(-runs="$RUNS")
  [ -n "${SECONDS_EACH:-}" ] && limit=(-max_total_time="$SECONDS_EACH")
  start=$(date +%s)
  if ! (cd "$work" && "$bin_dir/fuzz_$h" "${limit[@]}" -seed=1 -rss_limit_mb=2048 \
        -timeout=20 -print_final_stats=1 . "$OLDPWD/$corpus" >log.txt 2>&1); then
    status=1
    echo "fuzz_$h: FAILED, see $work/log.txt"
  fi
  runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$work/log.txt" | grep -o '[0-9]*$' || echo "?")
  echo "fuzz_$h: $runs inputs in $(( $(date +%s) - start )) s"
done
exit $status
