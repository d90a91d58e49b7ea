#!/bin/bash
# SPDX-License-Identifier: MIT
# P-SLAM prediction cost: (1) time per prediction on a 44 m x 34 m KTH plan explored for
# 600 s (the largest shared plan of the 50 m x 40 m class), at 20 frontier cells; (2) the
# RBPF's speed on the real fr101 log with and without --predict (predictions on the worker
# thread must not slow the filter). Run from the repository root after building:
#   bash bench/pslam/prediction_cost.sh
set -euo pipefail
cd "$(dirname "$0")/../.."
out=out/bench/pslam_cost
mkdir -p "$out"
plan=../shared/data/floorplans/kth/p2explore/floor_plans/50052750.png0.png0.png
./build/lookahead explore --world "$plan" --resolution 0.2 --pixel-rule only_white --pose truth \
  --robot-radius 0.15 --laser-range 12 --laser-fov 360 --time-limit 600 --coverage-goal 0.99 \
  --no-animation --out "$out/explore" > "$out/explore.txt" 2>&1
echo "map: $(grep -o '[0-9]* x [0-9]*' "$out/explore/map.pgm" 2>/dev/null || head -c 20 "$out/explore/map.pgm" | sed -n 2p) pixels"
i=0
for t in $(python3 bench/pslam/frontier_cells.py "$out/explore/map.yaml" 20 1); do
  ./build/lookahead predict "$out/explore/map.yaml" --target "$t" --out "$out/predict_$i" > /dev/null 2>&1 || true
  i=$((i + 1))
done
python3 - "$out" <<'PY'
import json, glob, statistics, sys
runs = [json.load(open(f)) for f in sorted(glob.glob(sys.argv[1] + '/predict_*/prediction.json'))]
ms = sorted(1000 * r['seconds'] for r in runs)
status = {s: sum(r['status'] == s for r in runs) for s in ('predicted', 'no_match', 'no_control_point')}
print(f"{len(runs)} predictions on the explored plan: median {statistics.median(ms):.0f} ms, "
      f"max {max(ms):.0f} ms; {status}")
PY
log=../shared/data/fr101/fr101.carmen.log
REPS=${REPS:-4}
for rep in $(seq 1 "$REPS"); do  # alternating, so both see the same load
  for mode in plain predict; do
    # Live mode: the filter must not wait for predictions (a replay would wait by default).
    flag=""; [ "$mode" = predict ] && flag="--predict --config config/slam/pslam_live.yaml"
    ./build/lookahead slam "$log" --particles 30 $flag --out "$out/fr101_${mode}_$rep" > /dev/null 2>&1
  done
done
python3 - "$out" "$REPS" <<'PY'
import json, statistics, sys
d, reps = sys.argv[1], int(sys.argv[2])
def rate(mode):
    runs = [json.load(open(f"{d}/fr101_{mode}_{r}/run.json")) for r in range(1, reps + 1)]
    return [r['updates'] / r['wall_time_s'] for r in runs], [r.get('prediction') for r in runs]
plain, _ = rate('plain'); pred, p = rate('predict')
print(f"fr101, 30 particles, filter updates per second (median of {reps}): plain {statistics.median(plain):.1f}, "
      f"with --predict {statistics.median(pred):.1f} (ratio {statistics.median(pred) / statistics.median(plain):.2f})")
print("predictions per run (requests, hypotheses):", [(x['requests'], x['hypotheses']) for x in p])
PY
