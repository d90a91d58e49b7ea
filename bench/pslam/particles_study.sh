#!/bin/bash
# SPDX-License-Identifier: MIT
# P-SLAM reproduction 4 (Chang et al. 2007, sec. V-B.3, Fig. 18): real scans of the Intel lab
# and fr079 with synthetic odometry (bench/tools/synth_odometry), Kuemmerle relative error of
# P-SLAM with 40 particles against the plain RBPF with 40 and with 200, and the KL divergence
# (eq. 24) of each final map from the map of a 1000-particle RBPF run.
# Usage (repository root, after building): bash bench/pslam/particles_study.sh
#   LOGS="intel-lab fr079" SEEDS="1 2" REFERENCE=1000 to change what runs.
set -euo pipefail
cd "$(dirname "$0")/../.."
DATA=${LOOKAHEAD_SHARED_DIR:-../shared}/data
LOGS=${LOGS:-"intel-lab fr079"}
SEEDS=${SEEDS:-"1"}
REFERENCE=${REFERENCE:-1000}
OUT=out/bench/pslam_particles
LA=./build/lookahead
mkdir -p "$OUT"
declare -A REL=([intel-lab]=intel/intel.relations [fr079]=fr079/fr079.relations)
echo "| log | odometry seed | filter | relative error m (mean +- std) | rot. deg | KL from ${REFERENCE}-particle map [nats] | wall s | predictions used / rejected |"
echo "|---|---|---|---|---|---|---|---|"
for name in $LOGS; do
  for s in $SEEDS; do
    log=$OUT/$name-synth$s.log
    ./build/bench/synth_odometry "$DATA/derived-flirtlib/$name.log" "$log" --seed "$s" > /dev/null
    $LA slam "$log" --particles "$REFERENCE" --out "$OUT/$name-$s-ref" > /dev/null 2>&1
    for run in "rbpf 40" "pslam 40 --predict" "rbpf 200"; do
      read -r label n flag <<< "$run"
      dir=$OUT/$name-$s-$label-$n
      $LA slam "$log" --particles "$n" ${flag:-} --out "$dir" > /dev/null 2>&1
      err=$($LA eval --trajectory "$dir/trajectory.txt" --relations "$DATA/${REL[$name]}" --json | tail -1)
      kl=$($LA eval --map "$dir/map.yaml" --reference-map "$OUT/$name-$s-ref/map.yaml" --json | tail -1)
      python3 - "$name" "$s" "$label $n" "$err" "$kl" "$dir/run.json" <<'PY'
import json, sys
name, seed, label, err, kl, run = sys.argv[1:]
e, k, r = json.loads(err), json.loads(kl), json.load(open(run))
p = r.get('prediction')
pred = f"{p['used']} / {p['rejected_by_hit_ratio']} ({p['hypotheses']} hypotheses)" if p else "-"
print(f"| {name} | {seed} | {label} | {e['trans_mean_m']:.3f} +- {e['trans_std_m']:.3f} | {e['rot_mean_deg']:.2f} | "
      f"{k['kl_divergence_nats']:.0f} | {r['wall_time_s']:.0f} | {pred} |")
PY
    done
  done
done
