#!/bin/bash
# SPDX-License-Identifier: MIT
# P-SLAM reproduction 1, where the time goes: full-coverage missions on the maze (true pose,
# seeds 1-5, JOBS at a time, default 1) of nearest and of predictive under each skip rule in
# bench/pslam/maze_skip_rules/, with debug logs, then the table of summarize_maze_skips.py.
# Run from the repository root after building:
#   bash bench/pslam/maze_skip_rules.sh [RULE ...]     (default: every rule)
# (LOOKAHEAD=/path/to/lookahead picks another binary; COVERAGE=0.95 ends at the 95 % goal instead
# of full coverage, predicted free space counting for the predictive runs; OUT=folder;
# JOBS=2 runs two missions at a time; STRATEGY=predictive-utility runs the rules on that
# strategy instead of predictive, in folders named RULE@predictive-utility; SEEDS="6 7 8 9 10"
# runs other seeds than 1-5, into the same folders.)
# A rule file changes only what it names in the mission defaults. Since session 18 the defaults
# are the maze's rule (fallback_d14_boundary_slivers; region5_d10 writes out the defaults
# before): a file written before then names only what differed from those, so its figures
# come back at the commit the README names for them, or with region5_d10's keys added.
set -euo pipefail
cd "$(dirname "$0")/../.."
bin=${LOOKAHEAD:-./build/lookahead}
coverage=${COVERAGE:-1.0}
out=${OUT:-out/maze_skip_rules_$coverage}
jobs=${JOBS:-1}
strategy=${STRATEGY:-predictive}
read -r -a seeds <<< "${SEEDS:-1 2 3 4 5}"
rules=("$@")
if [ ${#rules[@]} -eq 0 ]; then
  for f in bench/pslam/maze_skip_rules/*.yaml; do rules+=("$(basename "$f" .yaml)"); done
fi
run() {  # tag, then the arguments of explore
  local tag=$1; shift
  mkdir -p "$out/$tag"
  local n=0
  for s in "${seeds[@]}"; do
    SPDLOG_LEVEL=debug nice -n 10 "$bin" explore --world maze --pose truth --coverage-goal "$coverage" --seed "$s" \
      --out "$out/$tag/$s" "$@" > "$out/$tag/$s.log" 2>&1 &
    n=$((n + 1))
    if (( n % jobs == 0 )); then wait; fi
  done
  wait
}
[ -f "$out/nearest/${seeds[-1]}/run.json" ] || run nearest --strategy nearest
tags=()
for r in "${rules[@]}"; do
  tag=$r
  [ "$strategy" = predictive ] || tag="$r@$strategy"
  tags+=("$tag")
  run "$tag" --strategy "$strategy" --config "bench/pslam/maze_skip_rules/$r.yaml"
done
python3 bench/pslam/summarize_maze_skips.py "$out" nearest "${tags[@]}" | tee "$out/summary.md"
