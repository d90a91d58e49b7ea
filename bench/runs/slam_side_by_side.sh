#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# lookahead's RBPF and MRPT's rbpf-slam, side by side in one run on the same inputs:
#   A. accuracy on Intel and fr079 (real scans, SYNTHETIC odometry, seeds 1..3), Kuemmerle
#      relative error against the benchmark relations, 30 particles each;
#   B. the raw fr101 and MIT CSAIL logs (real odometry): wall time, peak memory, and on fr101
#      the error against GMapping's corrected trajectory;
#   C. our scaling on fr101 at 30, 100, 300 and 1000 particles.
# Usage: bench/runs/slam_side_by_side.sh [BUILD_DIR=build] [OUT=out/slam_side_by_side]
# Prints a markdown report and writes it to OUT/report.md with the commit, date and CPU.
set -euo pipefail
cd "$(dirname "$0")/../.."
BUILD=${1:-build}
OUT=${2:-out/slam_side_by_side}
DATA=${LOOKAHEAD_SHARED_DIR:-../shared}/data
SEEDS=${SEEDS:-"1 2 3"}
SCALING=${SCALING:-"30 100 300 1000"}
LA=$BUILD/lookahead
export CARMEN_TO_RAWLOG=$BUILD/bench/mrpt/carmen_to_rawlog
mkdir -p "$OUT"
[[ -x $LA ]] || { echo "build first: cmake --build $BUILD" >&2; exit 1; }

# Wall seconds and peak MB of a command, from GNU time (the same meter for both systems).
measure() {  # measure NAME cmd...
  local name=$1; shift
  /usr/bin/time -f "%e %M" -o "$OUT/$name.time" "$@" > "$OUT/$name.out" 2>&1 || {
    echo "FAILED: $*" >&2; tail -5 "$OUT/$name.out" >&2; return 1; }
  awk '{printf "%.1f %.0f", $1, $2/1024}' "$OUT/$name.time"
}
rel_error() {  # rel_error TRAJ RELATIONS -> "trans_mean trans_std rot_mean used"
  "$LA" eval --trajectory "$1" --relations "$2" --json | tail -1 |
    python3 -c 'import json,sys; j=json.load(sys.stdin); print("%.3f %.3f %.2f %d"%(j["trans_mean_m"],j["trans_std_m"],j["rot_mean_deg"],j["relations_used"]))'
}
to_logger_time() {  # to_logger_time MRPT_TRAJ OUR_TRAJ OUR_LOGGER_TRAJ OUT: restamp by scan (same ipc stamps)
  python3 - "$@" <<'PY'
import sys
mrpt, ipc, logger, out = sys.argv[1:]
rows = lambda f: [l.split() for l in open(f) if not l.startswith('#')]
key = lambda t: round(float(t), 4)
clock = {key(a[0]): b[0] for a, b in zip(rows(ipc), rows(logger))}
with open(out, 'w') as o:
    for r in rows(mrpt):
        if key(r[0]) in clock: o.write(' '.join([clock[key(r[0])]] + r[1:]) + '\n')
PY
}
ref_error() {  # ref_error TRAJ REFLOG -> "rel_rot_mean ate_rmse"
  "$LA" eval --trajectory "$1" --reference-log "$2" --tolerance 0.051 --json | tail -1 |
    python3 -c 'import json,sys; j=json.load(sys.stdin); print("%.2f %.3f"%(j["rot_mean_deg"],j["ate_rmse_m"]))'
}

{
echo "# lookahead vs MRPT rbpf-slam, side by side"
echo
echo "commit $(git rev-parse --short HEAD), $(date -u +%F), $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs), $(nproc) cores"
echo
echo "## A. Accuracy, real scans + synthetic odometry (30 particles; relative error vs relations)"
echo
echo "| log | odometry seed | system | trans. m (mean +- std) | rot. deg | relations | wall s |"
echo "|---|---|---|---|---|---|---|"
for d in intel-lab:intel/intel.relations fr079:fr079/fr079.relations; do
  name=${d%%:*}; rel=$DATA/${d##*:}
  for s in $SEEDS; do
    log=$OUT/$name-synth$s.log
    "$BUILD/bench/synth_odometry" "$DATA/derived-flirtlib/$name.log" "$log" --seed "$s" > /dev/null
    t=$(measure "la-$name-$s" "$LA" slam "$log" --out "$OUT/la-$name-$s" --particles 30)
    read -r tm ts rm n <<< "$(rel_error "$OUT/la-$name-$s/trajectory.txt" "$rel")"
    echo "| $name | $s | lookahead | $tm +- $ts | $rm | $n | ${t% *} |"
    t=$(measure "mrpt-$name-$s" bench/mrpt/run_mrpt_rbpf.sh "$log" "$OUT/mrpt-$name-$s" 30 optimal)
    read -r tm ts rm n <<< "$(rel_error "$OUT/mrpt-$name-$s/trajectory.txt" "$rel")"
    echo "| $name | $s | MRPT rbpf-slam (optimal) | $tm +- $ts | $rm | $n | ${t% *} |"
  done
done
echo
echo "## B. Raw logs with real odometry, 30 particles"
echo
echo "| log | system | wall s | x real time | peak MB | rel. rot. deg vs GMapping | ATE m vs GMapping |"
echo "|---|---|---|---|---|---|---|"
for d in fr101:fr101/fr101.carmen.log:1027 mit-csail:mit-csail/csail-oldcarmen.log:424; do
  IFS=: read -r name log dur <<< "$d"
  t=$(measure "la-$name" "$LA" slam "$DATA/$log" --out "$OUT/la-$name" --particles 30)
  err="- -"; [[ $name == fr101 ]] && err=$(ref_error "$OUT/la-$name/trajectory_logger_time.txt" "$DATA/fr101/fr101.carmen.gfs.log")
  echo "| $name | lookahead | ${t% *} | $(python3 -c "print(round($dur/${t% *},1))") | ${t#* } | ${err% *} | ${err#* } |"
  t=$(measure "mrpt-$name" bench/mrpt/run_mrpt_rbpf.sh "$DATA/$log" "$OUT/mrpt-$name" 30 optimal)
  err="- -"
  if [[ $name == fr101 ]]; then
    to_logger_time "$OUT/mrpt-$name/trajectory.txt" "$OUT/la-$name/trajectory.txt" \
      "$OUT/la-$name/trajectory_logger_time.txt" "$OUT/mrpt-$name/trajectory_logger_time.txt"
    err=$(ref_error "$OUT/mrpt-$name/trajectory_logger_time.txt" "$DATA/fr101/fr101.carmen.gfs.log")
  fi
  echo "| $name | MRPT rbpf-slam (optimal) | ${t% *} | $(python3 -c "print(round($dur/${t% *},1))") | ${t#* } | ${err% *} | ${err#* } |"
done
echo
echo "## C. lookahead scaling on fr101"
echo
echo "| particles | wall s | peak MB | ATE m vs GMapping |"
echo "|---|---|---|---|"
for n in $SCALING; do
  t=$(measure "la-fr101-$n" "$LA" slam "$DATA/fr101/fr101.carmen.log" --out "$OUT/la-fr101-$n" --particles "$n")
  err=$(ref_error "$OUT/la-fr101-$n/trajectory_logger_time.txt" "$DATA/fr101/fr101.carmen.gfs.log")
  echo "| $n | ${t% *} | ${t#* } | ${err#* } |"
done
} | tee "$OUT/report.md"
