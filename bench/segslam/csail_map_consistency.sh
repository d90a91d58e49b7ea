#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# How consistent the map a run writes is, on the raw MIT CSAIL log: the RMSE of the path the
# map was drawn along (SegSLAM: map_trajectory.txt, the minimum-entropy map's; the RBPF:
# trajectory.txt, its best particle's, along which its map was built) from the Radish
# reference after the best rigid alignment (bench/segslam/csail_error.py --global).
# SegSLAM runs twice per seed: with the defaults (offline.particle_chain on) and with the
# breadth-first samples only (the paper's search); the RBPF once.
#
# usage: [PARTICLES="5 20"] [RBPF_PARTICLES="40"] [FIRST_SEED=1] [RUNS=10] [JOBS=2] \
#        bench/segslam/csail_map_consistency.sh BUILD_DIR OUT_DIR
# prints one line per run: method particles seed final_m local_m global_m map_entropy offline_s
# (map_entropy: eq. 22 of the map written, gamma = cell area; paper sec. 5.4 compares SegSLAM's
# minimum-entropy map with the best RBPF map)
set -euo pipefail
BUILD=${1:?usage: csail_map_consistency.sh BUILD_DIR OUT_DIR}
OUT=${2:?usage: csail_map_consistency.sh BUILD_DIR OUT_DIR}
PARTICLES=${PARTICLES:-"5 20"}
RBPF_PARTICLES=${RBPF_PARTICLES:-"40"}
FIRST_SEED=${FIRST_SEED:-1}
RUNS=${RUNS:-10}
JOBS=${JOBS:-2}
HERE=$(cd "$(dirname "$0")" && pwd)
DATA=${DATA:-$HERE/../../../shared/data/mit-csail}
mkdir -p "$OUT"
python3 "$HERE/csail_truth.py" "$DATA/csail-oldcarmen.log" "$DATA/csail.corrected.log" > "$OUT/truth.txt"
printf 'offline:\n  particle_chain: false\n' > "$OUT/samples_only.yaml"

run() {  # method particles seed
  local dir=$OUT/runs/$1-$2-$3 extra=() path=trajectory.txt method=$1
  case $1 in
    segslam-samples) extra=(--segslam-config "$OUT/samples_only.yaml"); method=segslam ;;
  esac
  [[ $method == segslam ]] && path=map_trajectory.txt
  mkdir -p "$dir"
  "$BUILD/lookahead" slam "$DATA/csail-oldcarmen.log" --method "$method" --particles "$2" --seed "$3" --threads 1 \
    "${extra[@]}" --out "$dir" > "$dir.log" 2>&1
  local errors final_local entropy
  errors=$(python3 "$HERE/csail_error.py" "$dir/$path" "$OUT/truth.txt" --global)
  final_local=$(python3 "$HERE/csail_error.py" "$dir/trajectory.txt" "$OUT/truth.txt")
  # the written map's eq. 22 entropy [nats m^2]: SegSLAM's minimum-entropy map, the RBPF's best
  # particle's map (its map_entropy_nats times the cell area, 0.05 m cells as entropy_study.sh)
  entropy=$(python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); print(round(d.get("min_entropy_nats_m2", d.get("map_entropy_nats", 0) * 0.05 ** 2), 1), round(d.get("offline_search_s", 0), 1))' "$dir/run.json")
  echo "$1 $2 $3 $final_local ${errors##* } $entropy"
  rm -f "$dir"/*.pgm
}
export -f run
export OUT BUILD DATA HERE
{
  for n in $PARTICLES; do for s in $(seq "$FIRST_SEED" $((FIRST_SEED + RUNS - 1))); do
    echo "segslam $n $s"; echo "segslam-samples $n $s"; done; done
  for n in $RBPF_PARTICLES; do for s in $(seq "$FIRST_SEED" $((FIRST_SEED + RUNS - 1))); do echo "rbpf $n $s"; done; done
} | xargs -P "$JOBS" -L 1 bash -c 'run "$@"' _ | tee "$OUT/runs.txt"

python3 - "$OUT/runs.txt" <<'PY'
import collections, statistics as st, sys
by = collections.defaultdict(list)
for l in open(sys.argv[1]):
    m, n, s, final, local, glob, ent, off = l.split()
    by[(m, int(n))].append((float(glob), float(ent), float(off)))
print("| method | particles | runs | path RMSE after alignment m (mean / median / max) | map entropy (mean / least) | offline s (median) |")
print("|---|---:|---:|---|---|---:|")
for (m, n), v in sorted(by.items()):
    g = [x[0] for x in v]
    print(f"| {m} | {n} | {len(v)} | {st.mean(g):.2f} / {st.median(g):.2f} / {max(g):.2f} | "
          f"{st.mean(x[1] for x in v):.1f} / {min(x[1] for x in v):.1f} | {st.median(x[2] for x in v):.1f} |")
PY
