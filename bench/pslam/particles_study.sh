#!/bin/bash
# SPDX-License-Identifier: MIT
# P-SLAM reproduction 4 (Chang et al. 2007, sec. V-B.3, Fig. 18): real scans of the Intel lab
# and fr079 with synthetic odometry (bench/tools/synth_odometry, one log per odometry seed),
# Kuemmerle relative error of P-SLAM with 40 particles against the plain RBPF with 40 and
# with 200, and the KL divergence (eq. 24) of each final map from the map of a 1000-particle
# RBPF run on the same log. Two particle steps:
#   matching  our default, the scan-matching proposal;
#   standard  the paper's RBPF: sample the odometry model, weigh by the scan
#             (config/segslam/intel_loop_rbpf.yaml: the matcher always fails).
# The 1000-particle reference uses the scan-matching proposal for both.
# Filters: rbpf 40, pslam 40 (our predictor's defaults), pslam-paper 40 (without our
# conflict test, predictor.max_conflict_share 1: the paper's registration on Psi alone),
# rbpf 200.
# Predictions: the replay waits for each one (log_targets.wait_for_predictions, default),
# as a robot's filter at the sensor's rate would have it in time.
# Usage (repository root, after building):
#   bash bench/pslam/particles_study.sh [OUT]
#   LOGS="intel-lab fr079" SEEDS="1 2 3 4 5" PROPOSALS="matching standard" REFERENCE=1000
#   FILTER_SEEDS="1 2 3" (filter seeds per odometry log; runs of seeds > 1 end in -f<seed>)
#   FILTERS="rbpf-40 pslam-40" (a subset of rbpf-40 pslam-40 pslam-paper-40 rbpf-200)
# Finished runs (a run.json in their folder) are kept: rerunning resumes. The table is
# printed and written to OUT/summary.md; every run's figures to OUT/runs.tsv.
set -euo pipefail
cd "$(dirname "$0")/../.."
DATA=${LOOKAHEAD_SHARED_DIR:-../shared}/data
LOGS=${LOGS:-"intel-lab fr079"}
SEEDS=${SEEDS:-"1 2 3 4 5"}
PROPOSALS=${PROPOSALS:-"matching standard"}
FILTER_SEEDS=${FILTER_SEEDS:-"1"}
FILTERS=${FILTERS:-"rbpf-40 pslam-40 pslam-paper-40 rbpf-200"}
REFERENCE=${REFERENCE:-1000}
OUT=${1:-out/bench/pslam_particles}
LA=${LOOKAHEAD:-./build/lookahead}  # a copied binary lets you rebuild meanwhile
mkdir -p "$OUT"
declare -A REL=([intel-lab]=intel/intel.relations [fr079]=fr079/fr079.relations)
# One config file per (particle step, predictor): the sections of both in one file.
for proposal in matching standard; do
  for predictor in default paper; do
    f=$OUT/config-$proposal-$predictor.yaml
    : > "$f"
    [ "$proposal" = standard ] && cat config/segslam/intel_loop_rbpf.yaml >> "$f"
    [ "$predictor" = paper ] && printf 'predictor:\n  max_conflict_share: 1\n' >> "$f"
  done
done

run() {  # run DIR ARGS...: one lookahead slam run unless it is already there
  local dir=$1; shift
  [ -f "$dir/run.json" ] && return 0
  echo "$(date +%T) $dir" >&2
  $LA slam "$@" --out "$dir" > "$dir.log" 2>&1 || { echo "failed: $dir (see $dir.log)" >&2; return 1; }
}

tsv=$OUT/runs.tsv
columns=(log odometry_seed filter_seed proposal filter trans_mean_m trans_std_m rot_mean_deg kl_nats wall_s requests
         hypotheses used rejected)
(IFS=$'\t'; echo "${columns[*]}") > "$tsv"
for name in $LOGS; do
  for s in $SEEDS; do
    log=$OUT/$name-synth$s.log
    [ -f "$log" ] || ./build/bench/synth_odometry "$DATA/derived-flirtlib/$name.log" "$log" --seed "$s" > /dev/null
    ref=$OUT/$name-$s-ref$REFERENCE
    run "$ref" "$log" --particles "$REFERENCE"
    for proposal in $PROPOSALS; do
      for fs in $FILTER_SEEDS; do
      for filter in "rbpf 40 default" "pslam 40 default --predict" "pslam-paper 40 paper --predict" "rbpf 200 default"; do
        read -r label n predictor flag <<< "$filter"
        [[ " $FILTERS " == *" $label-$n "* ]] || continue
        dir=$OUT/$name-$s-$proposal-$label-$n
        [ "$fs" = 1 ] || dir=$dir-f$fs
        # shellcheck disable=SC2086
        run "$dir" "$log" --particles "$n" --seed "$fs" ${flag:-} --config "$OUT/config-$proposal-$predictor.yaml"
        err=$($LA eval --trajectory "$dir/trajectory.txt" --relations "$DATA/${REL[$name]}" --json | tail -1)
        kl=$($LA eval --map "$dir/map.yaml" --reference-map "$ref/map.yaml" --json | tail -1)
        python3 - "$name" "$s" "$fs" "$proposal" "$label $n" "$err" "$kl" "$dir/run.json" >> "$tsv" <<'PY'
import json, sys
name, seed, fseed, proposal, label, err, kl, run = sys.argv[1:]
e, k, r = json.loads(err), json.loads(kl), json.load(open(run))
p = r.get('prediction') or {}
print('\t'.join(str(x) for x in [name, seed, fseed, proposal, label, e['trans_mean_m'], e['trans_std_m'], e['rot_mean_deg'],
      k['kl_divergence_nats'], r['wall_time_s'], p.get('requests', '-'), p.get('hypotheses', '-'),
      p.get('used', '-'), p.get('rejected_by_hit_ratio', '-')]))
PY
      done
      done
    done
  done
done
python3 bench/pslam/summarize_particles.py "$tsv" | tee "$OUT/summary.md"
