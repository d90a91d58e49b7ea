#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# SegSLAM paper sec. 5.2 (Tables II and III) on a real 2D log with REAL odometry: the raw MIT
# CSAIL log (1988 scans, 380 m through the building's loops; odometry ends 21.5 m off), the
# RBPF against SegSLAM, each with its defaults (the RBPF's scan-matching proposal), RUNS runs
# (filter seeds) per particle count.
#
# Errors against the Radish corrected log (406 scans paired by their ranges,
# bench/runs/csail_truth.py; bench/runs/csail_error.py): the final error (the last
# paired scan relative to the first; the robot ends 0.7 m from its start) and the local error
# (relative poses 20 paired scans apart). Both filters write the best particle's trajectory
# (SegSLAM's reconstructed by eq. 11 with its matches). Run time: the filter's wall time from
# run.json, one thread each (--threads 1), JOBS runs at a time.
#
# Usage: bench/runs/segslam_csail.sh [BUILD=build] [OUT=out/segslam_csail]
#   env: RUNS (default 20), FIRST_SEED (default 1), PARTICLES (default "1 5 10 20 40"),
#   JOBS (default 2), METHODS (default "rbpf segslam"), SEGSLAM_CONFIG (optional
#   --segslam-config file), MAP_SAMPLES (default 1: SegSLAM's maps sampled for the
#   minimum-entropy map, sec. 5.4). The report covers every runs-*.txt in OUT, and the map
#   entropy of every run (SegSLAM: its minimum-entropy map; the RBPF: the best particle's map).
set -euo pipefail
cd "$(dirname "$0")/../.."
BUILD=${1:-build}
OUT=${2:-out/segslam_csail}
DATA=${LOOKAHEAD_SHARED_DIR:-../shared}/data/mit-csail
RUNS=${RUNS:-20}
FIRST_SEED=${FIRST_SEED:-1}
PARTICLES=${PARTICLES:-"1 5 10 20 40"}
JOBS=${JOBS:-2}
METHODS=${METHODS:-"rbpf segslam"}
SEGSLAM_CONFIG=${SEGSLAM_CONFIG:-}
MAP_SAMPLES=${MAP_SAMPLES:-1}
mkdir -p "$OUT/runs"
[[ -x $BUILD/lookahead ]] || { echo "build lookahead first" >&2; exit 1; }
python3 bench/runs/csail_truth.py "$DATA/csail-oldcarmen.log" "$DATA/csail.corrected.log" > "$OUT/truth.txt"

run() {  # run METHOD N SEED
  local dir=$OUT/runs/$1-$2-$3 extra=()
  [[ $1 == segslam && -n $SEGSLAM_CONFIG ]] && extra=(--segslam-config "$SEGSLAM_CONFIG")
  "$BUILD/lookahead" slam "$DATA/csail-oldcarmen.log" --method "$1" --particles "$2" --seed "$3" --threads 1 \
    --map-samples "$MAP_SAMPLES" "${extra[@]}" --out "$dir" > "$dir.log" 2>&1
  local errors time
  errors=$(python3 bench/runs/csail_error.py "$dir/trajectory.txt" "$OUT/truth.txt")
  time=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["wall_time_s"])' "$dir/run.json")
  echo "$1 $2 $3 $errors $time"
}
export -f run
export OUT BUILD DATA SEGSLAM_CONFIG MAP_SAMPLES
for n in $PARTICLES; do for s in $(seq "$FIRST_SEED" "$RUNS"); do for m in $METHODS; do echo "$m $n $s"; done; done; done |
  xargs -P "$JOBS" -L 1 bash -c 'run "$@"' _ | tee "$OUT/runs-$FIRST_SEED-$(date +%s).txt"

python3 - "$OUT" <<'PY' | tee "$OUT/report.md"
import statistics as st, sys, subprocess, collections, glob
rows = [l.split() for f in sorted(glob.glob(sys.argv[1] + '/runs-*.txt')) for l in open(f) if l.strip()]
by, seed_time = collections.defaultdict(list), collections.defaultdict(dict)
for m, n, s, final, local, t in rows:
    by[(m, int(n))].append((float(final), float(local), float(t)))
    seed_time[(int(n), s)][m] = float(t)
commit = subprocess.run(['git', 'rev-parse', '--short', 'HEAD'], capture_output=True, text=True).stdout.strip()
print(f"commit {commit}; MIT CSAIL raw log, real odometry; final error = last paired scan relative to the first")
print()
methods = [m for m in ('rbpf', 'segslam') if any(k[0] == m for k in by)]
print("| particles | runs | " + " | ".join(f"{m} final error m (mean / std / median)" for m in methods) + " | "
      + " | ".join(f"{m} runs under 1 m" for m in methods) + " | "
      + " | ".join(f"{m} local error m (mean)" for m in methods) + " | "
      + " | ".join(f"{m} time s (median)" for m in methods) + " | segslam / rbpf time (median of per-seed ratios) |")
print("|---|---|" + "---|" * (4 * len(methods) + 1))
def ratio(n):
    r = [d['segslam'] / d['rbpf'] for (k, _), d in seed_time.items() if k == n and len(d) == 2]
    return f"{st.median(r):.2f}" if r else "-"
def f(v):
    return f"{st.mean(v):.2f} / {st.stdev(v):.2f} / {st.median(v):.2f}" if len(v) > 1 else (f"{v[0]:.2f}" if v else "-")
for n in sorted({k[1] for k in by}):
    cells = [by.get((m, n), []) for m in methods]
    print(f"| {n} | {max(len(c) for c in cells)} | " + " | ".join(f([e for e, _, _ in c]) for c in cells) + " | "
          + " | ".join(str(sum(e < 1 for e, _, _ in c)) for c in cells) + " | "
          + " | ".join(f"{st.mean([l for _, l, _ in c]):.2f}" if c else "-" for c in cells) + " | "
          + " | ".join(f"{st.median([t for _, _, t in c]):.1f}" if c else "-" for c in cells) + " | " + ratio(n) + " |")

# Map entropy (SegSLAM eq. 22) in nats m^2: SegSLAM writes its minimum-entropy map's; the RBPF
# writes the best particle's map in nats (a sum over cells), scaled here by its cell area.
import json, os, re
entropy = collections.defaultdict(list)
for path in glob.glob(sys.argv[1] + '/runs/*/run.json'):
    j = json.load(open(path))
    m, n, _ = os.path.basename(os.path.dirname(path)).split('-')
    if 'min_entropy_nats_m2' in j:
        entropy[(m, int(n))].append(j['min_entropy_nats_m2'])
    elif 'map_entropy_nats' in j:
        cell = float(re.search(r'grid:\s*\n\s*resolution:\s*([0-9.eE+-]+)', j['configuration_yaml']).group(1))
        entropy[(m, int(n))].append(j['map_entropy_nats'] * cell * cell)
if entropy:
    print()
    print("| method | particles | runs | map entropy, least [nats m^2] | mean |")
    print("|---|---|---|---|---|")
    for (m, n), v in sorted(entropy.items()):
        print(f"| {m} | {n} | {len(v)} | {min(v):.1f} | {st.mean(v):.1f} |")
PY
