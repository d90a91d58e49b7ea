#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# SegSLAM paper sec. 5.2 (Tables II and III) on a 2D log: loop-closure error and run time of
# the RBPF and SegSLAM against the particle count, RUNS runs (filter seeds) each.
#
# The loop: Intel Research Lab, real scans 1098..1770 of shared/data/derived-flirtlib/
# intel-lab.log (88.6 m driven, the robot ends 0.97 m from where it started; the first
# place the log revisits with the same heading), with SYNTHETIC odometry
# (bench/tools/synth_odometry, seed 1, heading bias k_b = 0.02 rad/m: 7.1 m loop error for
# dead reckoning). Both filters run the paper's particle step (standard proposal, no scan
# matcher: config/segslam/intel_loop_rbpf.yaml), so closing the loop is the filter's problem.
#
# Final position error: the estimated pose of the last scan relative to the first, against
# the same relative pose of the scans' corrected poses (bench/segslam/loop_error.py). RBPF:
# the best particle's final pose (what `lookahead slam` writes); SegSLAM: the best particle's
# reconstructed trajectory (eq. 11, loops closed by its matches), brought to the last scan
# by dead reckoning. Also the paper's own measure (Table II: the weighted mean of the particle
# cloud, run.json `final_estimate`, both filters), the report's "mean-pose error" columns.
# Run time: the filter's wall time from run.json, one thread each
# (--threads 1), two runs at a time on a 2-core machine.
#
# Usage: bench/segslam/loop_study.sh [BUILD=build] [OUT=bench/results/segslam_loop]
#   env: RUNS (default 20), FIRST_SEED (default 1; seeds FIRST_SEED..RUNS, so a study can be
#   continued in the same OUT), PARTICLES (default "1 5 10 20 40 100"), JOBS (default 2),
#   METHODS (default "rbpf segslam"; SegSLAM with config/segslam/standard_proposal.yaml;
#   "segslam-locking" adds config/segslam/locking.yaml: locking and merging on;
#   "segslam-per-particle" adds matching.share_by_segment off: every particle searches its own
#   copy). The report covers every
#   runs-*.txt in OUT.
set -euo pipefail
cd "$(dirname "$0")/../.."
BUILD=${1:-build}
OUT=${2:-bench/results/segslam_loop}
DATA=${LOOKAHEAD_SHARED_DIR:-../shared}/data
RUNS=${RUNS:-20}
FIRST_SEED=${FIRST_SEED:-1}
PARTICLES=${PARTICLES:-"1 5 10 20 40 100"}
JOBS=${JOBS:-2}
METHODS=${METHODS:-"rbpf segslam"}
mkdir -p "$OUT"
[[ -x $BUILD/lookahead && -x $BUILD/bench/synth_odometry ]] || { echo "build lookahead and synth_odometry first" >&2; exit 1; }

# The one-loop log: scans 1098..1770 (VERTEX2 + ROBOTLASER1 pairs) and its synthetic odometry.
python3 - "$DATA/derived-flirtlib/intel-lab.log" "$OUT/intel-loop-truth.log" <<'PY'
import sys
records, current = [], None
for line in open(sys.argv[1]):
    if line.startswith('VERTEX2'):
        current = [line]
        records.append(current)
    elif current is not None:
        current.append(line)
with open(sys.argv[2], 'w') as out:
    for r in records[1098:1771]:
        out.writelines(r)
PY
"$BUILD/bench/synth_odometry" "$OUT/intel-loop-truth.log" "$OUT/intel-loop.log" --seed 1 --kb 0.02 > /dev/null

run() {  # run METHOD N SEED
  local dir=$OUT/runs/$1-$2-$3 method=(--method "$1")
  [[ $1 == segslam ]] && method=(--method segslam --segslam-config config/segslam/standard_proposal.yaml)
  [[ $1 == segslam-locking ]] && method=(--method segslam --segslam-config "$OUT/locking.yaml")
  [[ $1 == segslam-per-particle ]] && method=(--method segslam --segslam-config "$OUT/per_particle.yaml")
  "$BUILD/lookahead" slam "$OUT/intel-loop.log" "${method[@]}" --particles "$2" --seed "$3" --threads 1 \
    --config config/segslam/intel_loop_rbpf.yaml --map-samples 1 --out "$dir" > "$dir.log" 2>&1
  local err time mean_err
  err=$(python3 bench/segslam/loop_error.py "$dir/trajectory.txt" "$OUT/intel-loop-truth.log")
  mean_err=$(python3 bench/segslam/loop_error.py "$dir/trajectory.txt" "$OUT/intel-loop-truth.log" "$dir/run.json")
  time=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["wall_time_s"])' "$dir/run.json")
  echo "$1 $2 $3 $err $time $mean_err"
}
export -f run
export OUT BUILD
mkdir -p "$OUT/runs"
# SegSLAM runs the paper's segmentation here, as the particle step is the paper's
# (config/segslam/standard_proposal.yaml; the 2D defaults are set for the scan-matching
# proposal). segslam-per-particle: every particle searches its own copy of a segment (no
# screening); segslam-locking: locking and merging on (config/segslam/locking.yaml).
{ cat config/segslam/standard_proposal.yaml; printf '  share_by_segment: false\n'; } > "$OUT/per_particle.yaml"
{ cat config/segslam/standard_proposal.yaml; grep -v '^#' config/segslam/locking.yaml; } > "$OUT/locking.yaml"
for n in $PARTICLES; do for s in $(seq "$FIRST_SEED" "$RUNS"); do for m in $METHODS; do echo "$m $n $s"; done; done; done |
  xargs -P "$JOBS" -L 1 bash -c 'run "$@"' _ | tee "$OUT/runs-$FIRST_SEED.txt"

python3 - "$OUT" <<'PY' | tee "$OUT/report.md"
import statistics as st, sys, subprocess, collections, glob
rows = [l.split() for f in sorted(glob.glob(sys.argv[1] + '/runs-*.txt')) for l in open(f) if l.strip()]
by = collections.defaultdict(list)
seed_time = collections.defaultdict(dict)
mean_by = collections.defaultdict(list)
for m, n, s, e, t, *mean in rows:  # runs of before the mean-pose column have 5 fields
    by[(m, int(n))].append((float(e), float(t)))
    if mean:
        mean_by[(m, int(n))].append(float(mean[0]))
    seed_time[(int(n), s)][m] = float(t)
commit = subprocess.run(['git', 'rev-parse', '--short', 'HEAD'], capture_output=True, text=True).stdout.strip()
cpu = [l.split(':')[1].strip() for l in open('/proc/cpuinfo') if l.startswith('model name')][0]
print(f"commit {commit}, {cpu}; loaded machine (other builds running): times are indicative")
print()
methods = [m for m in ('rbpf', 'segslam', 'segslam-per-particle', 'segslam-locking') if any(k[0] == m for k in by)]
others = [m for m in methods if m != 'rbpf'] if 'rbpf' in methods else []
print("| particles | runs | " + " | ".join(f"{m} error m (mean / std)" for m in methods) + " | "
      + " | ".join(f"{m} mean-pose error m (mean / std)" for m in methods) + " | "
      + " | ".join(f"{m} time s (median)" for m in methods) + " | "
      + " | ".join(f"{m} / rbpf time (median of per-seed ratios)" for m in others) + " |")
print("|---|---|" + "---|" * (3 * len(methods) + len(others)))
def ratio(m, n):
    r = [d[m] / d['rbpf'] for (k, _), d in seed_time.items() if k == n and m in d and 'rbpf' in d]
    return f"{st.median(r):.2f}" if r else "-"
f = lambda v: f"{st.mean(v):.2f} / {st.stdev(v):.2f}" if len(v) > 1 else (f"{v[0]:.2f} / -" if v else "-")
med = lambda v: f"{st.median(v):.1f}" if v else "-"
for n in sorted({k[1] for k in by}):
    cells = [by.get((m, n), []) for m in methods]
    print(f"| {n} | {len(cells[0])} | " + " | ".join(f([e for e, _ in c]) for c in cells) + " | "
          + " | ".join(f(mean_by.get((m, n), [])) for m in methods) + " | "
          + " | ".join(med([t for _, t in c]) for c in cells) + " | "
          + " | ".join(ratio(m, n) for m in others) + " |")
PY
