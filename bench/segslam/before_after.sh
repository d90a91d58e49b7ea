#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Run time of two lookahead binaries (e.g. before and after a change) and of the RBPF, side
# by side in one batch on the loop study's log, so machine load hits all three alike.
#
# Usage: bench/segslam/before_after.sh BEFORE_BINARY AFTER_BINARY LOOP_DIR [OUT]
#   LOOP_DIR: an OUT of loop_study.sh (holds intel-loop.log and intel-loop-truth.log).
#   env: SEEDS (default "1 2 3"), PARTICLES (default "20 40"), JOBS (default 2).
# Prints one line per run: label particles seed error_m wall_time_s; then the medians and
# the median over seeds of the per-seed time ratios.
set -euo pipefail
cd "$(dirname "$0")/../.."
BEFORE=$1 AFTER=$2 LOOP=$3 OUT=${4:-bench/results/segslam_before_after}
SEEDS=${SEEDS:-"1 2 3"} PARTICLES=${PARTICLES:-"20 40"} JOBS=${JOBS:-2}
mkdir -p "$OUT"
run() {  # run LABEL BINARY METHOD N SEED
  local dir=$OUT/$1-$4-$5
  "$2" slam "$LOOP/intel-loop.log" --method "$3" --particles "$4" --seed "$5" --threads 1 \
    --config config/segslam/intel_loop_rbpf.yaml --map-samples 1 --out "$dir" > "$dir.log" 2>&1
  echo "$1 $4 $5 $(python3 bench/segslam/loop_error.py "$dir/trajectory.txt" "$LOOP/intel-loop-truth.log")" \
    "$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["wall_time_s"])' "$dir/run.json")"
}
export -f run
export OUT LOOP
for n in $PARTICLES; do for s in $SEEDS; do
  echo "rbpf $AFTER rbpf $n $s"; echo "segslam-before $BEFORE segslam $n $s"; echo "segslam-after $AFTER segslam $n $s"
done; done | xargs -P "$JOBS" -L 1 bash -c 'run "$@"' _ | tee "$OUT/runs.txt"
python3 - "$OUT/runs.txt" <<'PY'
import collections, statistics as st, sys
t = collections.defaultdict(dict)
for label, n, s, err, time in (l.split() for l in open(sys.argv[1]) if l.strip()):
    t[(int(n), s)][label] = float(time)
for n in sorted({k[0] for k in t}):
    cells = [d for (m, _), d in t.items() if m == n]
    med = {l: st.median(d[l] for d in cells) for l in ('rbpf', 'segslam-before', 'segslam-after')}
    ratio = lambda a, b: st.median(d[a] / d[b] for d in cells)
    print(f"{n} particles: median s RBPF {med['rbpf']:.2f}, SegSLAM before {med['segslam-before']:.2f}, "
          f"after {med['segslam-after']:.2f}; before/after {ratio('segslam-before', 'segslam-after'):.2f}, "
          f"SegSLAM/RBPF before {ratio('segslam-before', 'rbpf'):.2f}, after {ratio('segslam-after', 'rbpf'):.2f}")
PY
