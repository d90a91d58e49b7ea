#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Minimum-entropy map (SegSLAM sec. 5.4, eq. 20-22) in 3D, on the simulated garage loop:
# SegSLAM's least-entropy map of K full map samples against the 3D RBPF's best particle map
# at several particle counts (the paper: 10,755 against 13,561 for 200-particle RBPF), with
# the filter's and the offline search's run times. The same simulated log (--data-seed 1),
# filter seeds 1..RUNS; per seed the runs one after the other. Writes OUT/summary.md and
# every run's folder (map.bt, trajectory.png, run.json); resumable.
#
# usage: bench/seg3d/entropy_study.sh [OUT] [RUNS]
#   RBPF="40 100 200" SEGSLAM=40 SAMPLES=20 LOOKAHEAD=build/lookahead
set -euo pipefail
out=${1:-out/seg3d_entropy}
runs=${2:-3}
read -r -a rbpf <<< "${RBPF:-40 100 200}"
read -r -a segslam <<< "${SEGSLAM:-40}"
samples=${SAMPLES:-20}
bin=${LOOKAHEAD:-build/lookahead}
mkdir -p "$out"
for seed in $(seq 1 "$runs"); do
  for n in "${rbpf[@]}"; do
    dir="$out/rbpf-p$n-s$seed"
    [ -f "$dir/run.json" ] && continue
    echo "rbpf, particles $n, seed $seed"
    "$bin" slam3d garage --method rbpf --particles "$n" --seed "$seed" --data-seed 1 --out "$dir" > "$dir.log" 2>&1
  done
  for n in "${segslam[@]}"; do
    dir="$out/segslam-p$n-s$seed"
    [ -f "$dir/run.json" ] && continue
    echo "segslam, particles $n, $samples map samples, seed $seed"
    "$bin" slam3d garage --method segslam --particles "$n" --seed "$seed" --data-seed 1 --map-samples "$samples" \
      --out "$dir" > "$dir.log" 2>&1
  done
done
python3 - "$out" "$(git rev-parse --short HEAD)" <<'PY'
import glob, json, os, statistics as st, sys
out, commit = sys.argv[1:3]
rows = {}
for f in sorted(glob.glob(os.path.join(out, '*-p*-s*/run.json'))):
    j = json.load(open(f))
    rows.setdefault((j['method'], j['particles']), []).append(j)
sd = lambda v: st.stdev(v) if len(v) > 1 else float('nan')
lines = ['| method | particles | runs | map entropy, eq. 22 [nats m^3] mean / std | known voxels (mean) | final error [m] mean / std | filter time median [s] | offline search median [s] | map samples |',
         '|---|---:|---:|---|---:|---|---:|---:|---:|']
for (m, n) in sorted(rows, key=lambda k: (k[0], k[1])):
    r = rows[(m, n)]
    h = [x['map_entropy_nats_m3'] for x in r]
    e = [x['final_position_error_m'] for x in r]
    off = st.median(x.get('offline_search_s', 0.0) for x in r)
    k = r[0].get('map_samples', '-')
    lines.append(f"| {m} | {n} | {len(r)} | {st.mean(h):.0f} / {sd(h):.0f} | {st.mean(x['map_known_voxels'] for x in r):.0f} | "
                 f"{st.mean(e):.2f} / {sd(e):.2f} | {st.median(x['wall_time_s'] for x in r):.1f} | "
                 f"{off:.1f} | {k} |")
per_seed = ['', '| seed | ' + ' | '.join(f'{m} {n}' for (m, n) in sorted(rows)) + ' |',
            '|---:|' + '---:|' * len(rows)]
seeds = sorted({x['seed'] for r in rows.values() for x in r})
for s in seeds:
    cells = []
    for k in sorted(rows):
        v = [x['map_entropy_nats_m3'] for x in rows[k] if x['seed'] == s]
        cells.append(f'{v[0]:.0f}' if v else '-')
    per_seed.append(f'| {s} | ' + ' | '.join(cells) + ' |')
head = f'Garage loop, minimum-entropy map (eq. 22, gamma = voxel volume); commit {commit}\n\n'
text = head + '\n'.join(lines) + '\n' + '\n'.join(per_seed) + '\n'
open(os.path.join(out, 'summary.md'), 'w').write(text)
print(text)
PY
