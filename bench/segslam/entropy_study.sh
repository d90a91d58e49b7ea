#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# SegSLAM paper sec. 5.4: the minimum-entropy map of SegSLAM (offline search over map
# samples, eq. 20-22 with gamma = cell area) against the best RBPF map (the least entropy of
# the best particles' maps over RUNS runs at 40 and 100 particles), on the Intel loop of
# loop_study.sh (run that first: it writes OUT/intel-loop.log). Entropies in nats m^2 over
# observed cells; the RBPF's from run.json's map_entropy_nats times the cell area.
# Usage: bench/segslam/entropy_study.sh [BUILD=build] [LOOP_OUT=bench/results/segslam_loop]
#   env: RUNS (default 3), SAMPLES (default 100), SEGSLAM_PARTICLES (default 40)
set -euo pipefail
cd "$(dirname "$0")/../.."
BUILD=${1:-build}
LOOP=${2:-bench/results/segslam_loop}
RUNS=${RUNS:-3}
SAMPLES=${SAMPLES:-100}
NSEG=${SEGSLAM_PARTICLES:-40}
OUT=$LOOP/entropy
LOG=$LOOP/intel-loop.log
[[ -f $LOG ]] || { echo "run bench/segslam/loop_study.sh first ($LOG missing)" >&2; exit 1; }
mkdir -p "$OUT"
field() { python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))[sys.argv[2]])' "$1" "$2"; }
{
echo "| method | particles | seed | entropy nats m^2 | filter s | offline search s |"
echo "|---|---|---|---|---|---|"
for s in $(seq 1 "$RUNS"); do
  d=$OUT/segslam-$NSEG-$s
  "$BUILD/lookahead" slam "$LOG" --method segslam --particles "$NSEG" --seed "$s" --threads 1 \
    --config config/segslam/intel_loop_rbpf.yaml --map-samples "$SAMPLES" --out "$d" > "$d.log" 2>&1
  echo "| SegSLAM min-entropy of $SAMPLES samples | $NSEG | $s | $(printf %.1f "$(field "$d/run.json" min_entropy_nats_m2)") | $(printf %.1f "$(field "$d/run.json" wall_time_s)") | $(printf %.1f "$(field "$d/run.json" offline_search_s)") |"
  for n in 40 100; do
    d=$OUT/rbpf-$n-$s
    "$BUILD/lookahead" slam "$LOG" --particles "$n" --seed "$s" --threads 1 \
      --config config/segslam/intel_loop_rbpf.yaml --out "$d" > "$d.log" 2>&1
    h=$(python3 -c 'import json,sys; j=json.load(open(sys.argv[1])); print("%.1f" % (j["map_entropy_nats"] * 0.05 ** 2))' "$d/run.json")
    echo "| RBPF best particle | $n | $s | $h | $(printf %.1f "$(field "$d/run.json" wall_time_s)") | - |"
  done
done
} | tee "$OUT/report.md"
