#!/bin/bash
# SPDX-License-Identifier: MIT
# P-SLAM reproduction 5 (Chang et al. 2007, sec. IV-B-1, Fig. 12-14): the L-shaped corridor
# with boxes (built-in world "corridor"), explored from A to C with SLAM in the loop, plain
# RBPF against P-SLAM (--predict: hypotheses in the particle weights). Bending is measured
# against the world: the SLAM position error along the way and at the end, and the map's
# precision and recall. Two runs at a time (both cores).
# Usage (repository root, after building): bash bench/pslam/corridor_study.sh [SEEDS] [OUT]
#   CONFIG=MISSION.yaml passes --config to both arms (e.g. config/mission/standard_proposal.yaml:
#   the paper's RBPF, which samples the motion model instead of our scan-matching proposal).
set -euo pipefail
cd "$(dirname "$0")/../.."
SEEDS=${1:-10}
OUT=${2:-out/bench/pslam_corridor}
export LA=${LOOKAHEAD:-./build/lookahead}  # a copy keeps a long study safe from rebuilds
export CONFIG_ARGS=${CONFIG:+--config $CONFIG}
mkdir -p "$OUT"
for s in $(seq 1 "$SEEDS"); do
  echo "rbpf $s"
  echo "pslam $s --predict"
done | xargs -P 2 -L 1 bash -c 'label=$0; seed=$1; shift 1; dir='"$OUT"'/$label-$seed;
  [ -f "$dir/run.json" ] || "$LA" explore $CONFIG_ARGS --world corridor --seed "$seed" --no-animation "$@" --out "$dir" > "$dir.log" 2>&1;
  echo "$label seed $seed done"'
python3 bench/pslam/summarize_corridor.py "$OUT" | tee "$OUT/summary.md"
