#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The SLAM accuracy table: every raw log with real odometry x seeds, lookahead's RBPF and
# MRPT's rbpf-slam (optimal sampling) side by side, at the same particle count.
#   fr101 (GMapping's fr101.carmen.gfs.log as reference), MIT CSAIL in both CARMEN formats
#   (Radish csail.corrected.log), and the MRPT one-loop rawlog (no reference: time, memory).
# Per run: relative rotation between consecutive reference scans, ATE after SE(2) alignment
# (bench/slam/reference_error.py), wall and CPU (user + sys) seconds and peak memory (GNU time).
# Usage: bench/slam/accuracy_table.sh [BUILD_DIR=build] [OUT=out/accuracy_table]
# env: SEEDS (default 1..10), MRPT_SEEDS (default: SEEDS; "" skips MRPT), PARTICLES (30),
#      THREADS (lookahead worker threads, default 1), JOBS (runs at once, default 1),
#      CONFIG (a lookahead slam YAML relative to the repository, default: config/slam/default.yaml, the code's defaults).
# Writes OUT/report.md (commit, date, CPU, configuration, the table, mean and worst seed).
set -euo pipefail
cd "$(dirname "$0")/../.."
BUILD=${1:-build}
OUT=${2:-out/accuracy_table}
DATA=${LOOKAHEAD_SHARED_DIR:-../shared}/data
SEEDS=${SEEDS:-"1 2 3 4 5 6 7 8 9 10"}
MRPT_SEEDS=${MRPT_SEEDS-$SEEDS}
PARTICLES=${PARTICLES:-30}
THREADS=${THREADS:-1}
JOBS=${JOBS:-1}
CONFIG=${CONFIG:-config/slam/default.yaml}
LA=$BUILD/lookahead
ONE_LOOP="/usr/share/mrpt/datasets/2006-01ENE-21-SENA_Telecom Faculty_one_loop_only.rawlog"
[[ -x $LA ]] || { echo "build first: cmake --build $BUILD --target lookahead carmen_to_rawlog" >&2; exit 1; }
[[ -x /usr/bin/time ]] || { echo "/usr/bin/time missing: apt-get install time" >&2; exit 1; }
export CARMEN_TO_RAWLOG=$PWD/$BUILD/bench/mrpt/carmen_to_rawlog
mkdir -p "$OUT/runs"
OUT=$(cd "$OUT" && pwd)

# log name : raw log : reference (empty: none)
LOGS=(
  "fr101:$DATA/fr101/fr101.carmen.log:$DATA/fr101/fr101.carmen.gfs.log"
  "csail-old:$DATA/mit-csail/csail-oldcarmen.log:$DATA/mit-csail/csail.corrected.log"
  "csail-new:$DATA/mit-csail/csail-newcarmen.log:$DATA/mit-csail/csail.corrected.log"
  "mrpt-one-loop:$ONE_LOOP:"
)

# One run: writes runs/SYSTEM-LOG-SEED/{trajectory.txt,time.txt} and a row file.
run_one() {  # run_one SYSTEM NAME LOG REF SEED
  local sys=$1 name=$2 log=$3 ref=$4 seed=$5 dir="$OUT/runs/$1-$2-$5"
  mkdir -p "$dir"
  if [[ $sys == lookahead ]]; then
    /usr/bin/time -f "%e %U %S %M" -o "$dir/time.txt" "$LA" slam "$log" --out "$dir" \
      --config "$CONFIG" --particles "$PARTICLES" --seed "$seed" --threads "$THREADS" > "$dir/console.txt" 2>&1 ||
      { echo "FAILED: lookahead on $log seed $seed, see $dir/console.txt" >&2; return 0; }
  elif [[ $log == *.rawlog ]]; then  # rbpf-slam reads the rawlog itself; no trajectory kept
    sed -e "s#@OUT_DIR@#$dir/mrpt#" -e "s#@PARTICLES@#$PARTICLES#" -e "s#@SEED@#$seed#" \
      bench/mrpt/rbpf_slam_gridmap.ini > "$dir/rbpf_slam.ini"
    /usr/bin/time -f "%e %U %S %M" -o "$dir/time.txt" rbpf-slam "$dir/rbpf_slam.ini" "$log" \
      < /dev/null > "$dir/console.txt" 2>&1 ||
      { echo "FAILED: rbpf-slam on $log seed $seed, see $dir/console.txt" >&2; return 0; }
  else
    SEED=$seed /usr/bin/time -f "%e %U %S %M" -o "$dir/time.txt" bench/mrpt/run_mrpt_rbpf.sh \
      "$log" "$dir" "$PARTICLES" optimal > "$dir/console.txt" 2>&1 ||
      { echo "FAILED: rbpf-slam on $log seed $seed, see $dir/console.txt" >&2; return 0; }
  fi
  local err="- - - -"
  [[ -n $ref ]] && err=$(python3 bench/slam/reference_error.py "$log" "$ref" "$dir/trajectory.txt")
  read -r wall user sys_s kb < "$dir/time.txt"
  echo "$name $sys $seed $err $wall $(awk "BEGIN{print $user + $sys_s}") $((kb / 1024))" > "$dir/row.txt"
}
export -f run_one
export OUT LA PARTICLES THREADS CONFIG

for entry in "${LOGS[@]}"; do
  IFS=: read -r name log ref <<< "$entry"
  [[ -f $log ]] || { echo "missing $log, skipped" >&2; continue; }
  for s in $SEEDS; do printf '%s\0' lookahead "$name" "$log" "$ref" "$s"; done
  for s in $MRPT_SEEDS; do printf '%s\0' mrpt "$name" "$log" "$ref" "$s"; done
done | xargs -0 -n5 -P"$JOBS" bash -c 'run_one "$@"' _

{
  echo "# SLAM accuracy table, $PARTICLES particles"
  echo
  echo "commit $(git rev-parse --short HEAD)$(git diff --quiet HEAD || echo ' (modified)'), $(date -u '+%F %H:%M UTC')," \
       "$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs), $(nproc) cores," \
       "load $(cut -d' ' -f1-3 /proc/loadavg); lookahead threads $THREADS, runs at once $JOBS"
  echo
  echo "lookahead: $CONFIG with --particles $PARTICLES --seed S --threads $THREADS;" \
       "MRPT: rbpf-slam (mrpt-apps $(dpkg-query -W -f='${Version}' mrpt-apps 2>/dev/null || echo '?'))," \
       "bench/mrpt/rbpf_slam_gridmap.ini (optimal sampling)."
  echo "References are GMapping outputs (fr101.carmen.gfs.log, csail.corrected.log), not ground truth;" \
       "the MRPT one-loop log has none. Relative rotation: between consecutive reference scans."
  echo
  echo "| log | system | seed | rel. rot. deg | ATE RMSE m | ATE max m | paired | wall s | CPU s | peak MB |"
  echo "|---|---|---|---|---|---|---|---|---|---|"
  cat "$OUT"/runs/*/row.txt 2>/dev/null | sort -k1,1 -k2,2 -k3,3n | awk -v OFS=' | ' '{$1 = $1; print "| " $0 " |"}'
  echo
  echo "## Per log and system: mean and worst seed"
  echo
  echo "| log | system | runs | rel. rot. mean (worst) deg | ATE mean (worst) m | CPU median s | peak MB max |"
  echo "|---|---|---|---|---|---|---|"
  cat "$OUT"/runs/*/row.txt 2>/dev/null | python3 -c '
import sys, statistics as st
rows = {}
for l in sys.stdin:
    f = l.split(); rows.setdefault((f[0], f[1]), []).append(f)
num = lambda v: None if v == "-" else float(v)
for (log, sysname), rs in sorted(rows.items()):
    rot = [num(r[3]) for r in rs if num(r[3]) is not None]
    ate = [num(r[4]) for r in rs if num(r[4]) is not None]
    cpu = [float(r[8]) for r in rs]; mem = [int(r[9]) for r in rs]
    f = lambda v, d: "%.*f (%.*f)" % (d, st.mean(v), d, max(v)) if v else "-"
    print("| %s | %s | %d | %s | %s | %.1f | %d |" % (log, sysname, len(rs), f(rot, 2), f(ate, 3), st.median(cpu), max(mem)))
'
} > "$OUT/report.md"
cat "$OUT/report.md"
