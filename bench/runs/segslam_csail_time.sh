#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# SegSLAM's time against two RBPFs, side by side in one run on the raw MIT CSAIL log:
# lookahead's SegSLAM, lookahead's RBPF (copy-on-write maps) and MRPT's rbpf-slam (Debian
# mrpt-apps, "optimal sampling", the settings of BASELINES.md; every particle owns its map).
# One run at a time, one thread each (MRPT is single-threaded), so the wall times compare.
#
#   bench/runs/segslam_csail_time.sh [BUILD=build] [OUT=out/segslam_csail_time]
#   env: PARTICLES (default "20 40 100"), SEEDS (default "1 2 3"),
#        METHODS (default "rbpf segslam mrpt"; also segslam-noseg: SegSLAM's filter that never
#        segments, so one submap, and segslam-nomatch: segments that are never re-entered
#        (min_separation_s 1e6), the floors of what SegSLAM adds to the RBPF's particle step)
#
# Writes OUT/runs.txt (method particles seed process_s filter_s final_m peak_mb; filter_s is
# our filters' own wall time from run.json, "-" for MRPT, which does not report one; final_m
# the final error against the Radish reference, bench/runs/csail_error.py) and prints
# OUT/summary.md: the medians per cell and the median of the per-seed time ratios.
set -euo pipefail
cd "$(dirname "$0")/../.."
die() { echo "csail_rbpf_time.sh: $*" >&2; exit 1; }
[[ $# -le 2 ]] || die "usage: csail_rbpf_time.sh [BUILD] [OUT]"
BUILD=${1:-build}
OUT=${2:-out/segslam_csail_time}
DATA=${LOOKAHEAD_SHARED_DIR:-../shared}/data/mit-csail
PARTICLES=${PARTICLES:-"20 40 100"}
SEEDS=${SEEDS:-"1 2 3"}
LA=$BUILD/lookahead
LOG=$DATA/csail-oldcarmen.log
[[ -x $LA ]] || die "$LA missing: build first (cmake --build $BUILD)"
[[ -f $LOG ]] || die "$LOG: no such file"
[[ -x /usr/bin/time ]] || die "/usr/bin/time missing: apt-get install time"
export CARMEN_TO_RAWLOG=$BUILD/bench/mrpt/carmen_to_rawlog
mkdir -p "$OUT"
TRUTH=$OUT/csail-truth.txt
python3 bench/runs/csail_truth.py "$LOG" "$DATA/csail.corrected.log" > "$TRUTH"

final_error() { python3 bench/runs/csail_error.py "$1" "$TRUTH" | awk '{print $1}'; }
# Our runs say which code they timed; an uncommitted tree is marked -dirty.
COMMIT=$(git describe --always --dirty)
filter_s() { python3 -c 'import json,sys; print(round(json.load(open(sys.argv[1]))["wall_time_s"], 2))' "$1"; }

METHODS=${METHODS:-"rbpf segslam mrpt"}
for m in $METHODS; do
  [[ $m =~ ^(rbpf|segslam|segslam-noseg|segslam-nomatch|mrpt)$ ]] || die "unknown method '$m' in METHODS"
done
printf 'segmentation:\n  max_motion_error: 1000000\n' > "$OUT/noseg.yaml"
printf 'matching:\n  min_separation_s: 1000000\n' > "$OUT/nomatch.yaml"

RUNS=$OUT/runs.txt
echo "# method particles seed process_s filter_s final_m peak_mb ($COMMIT, $(date -u +%F), $(nproc) cores)" > "$RUNS"
for n in $PARTICLES; do
  for s in $SEEDS; do
    for m in $METHODS; do
      d=$OUT/$m-p$n-s$s
      case $m in
        mrpt)
          OMP_NUM_THREADS=1 SEED=$s bench/mrpt/run_mrpt_rbpf.sh "$LOG" "$d" "$n" optimal > "$d.log" 2>&1 || die "MRPT failed, see $d.log"
          read -r wall peak <<< "$(python3 -c 'import json,sys; j=json.load(open(sys.argv[1])); print(j["wall_s"], int(j["peak_mb"]))' "$d/mrpt_run.json")"
          err=$(final_error "$d/trajectory.txt") && [[ -n $err ]] || die "no final error for $d"
          echo "mrpt $n $s $wall - $err $peak" | tee -a "$RUNS"
          continue ;;
        rbpf) args=(--method rbpf) ;;
        segslam) args=(--method segslam --map-samples 1) ;;
        segslam-noseg) args=(--method segslam --map-samples 1 --segslam-config "$OUT/noseg.yaml") ;;
        segslam-nomatch) args=(--method segslam --map-samples 1 --segslam-config "$OUT/nomatch.yaml") ;;
      esac
      /usr/bin/time -f "%e %M" -o "$d.time" "$LA" slam "$LOG" "${args[@]}" --particles "$n" --seed "$s" \
        --threads 1 --out "$d" > "$d.log" 2>&1 || die "$m failed, see $d.log"
      read -r wall kb < "$d.time"
      filt=$(filter_s "$d/run.json") && err=$(final_error "$d/trajectory.txt") && [[ -n $err ]] || die "no times or error for $d"
      echo "$m $n $s $wall $filt $err $((kb / 1024))" | tee -a "$RUNS"
    done
  done
done

python3 bench/runs/segslam_csail_time_summary.py "$RUNS" > "$OUT/summary.md"
cat "$OUT/summary.md"
