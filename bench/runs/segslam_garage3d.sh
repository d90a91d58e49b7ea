#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Loop-closure error and run time on the simulated garage loop against particle count
# (SegSLAM Tables II and III), the 3D RBPF and SegSLAM side by side: the same simulated log
# (--data-seed 1) filtered RUNS times per count and method with filter seeds 1..RUNS, the
# two methods of one seed and count run one after the other (same machine load). Writes
# OUT/summary.md and OUT/summary.json (commit, CPU, parameters), and every run's folder
# (map.bt, trajectory.png, run.json).
#
# usage: bench/runs/segslam_garage3d.sh [OUT] [RUNS] [COUNTS...]
#   e.g. METHODS="rbpf segslam" bench/runs/segslam_garage3d.sh out/segslam_garage3d 5 1 5 10 20 40
#   SEGSLAM_ARGS="--max-search-radius 0" passes options to the SegSLAM runs only.
set -euo pipefail
out=${1:-out/segslam_garage3d}
runs=${2:-5}
shift $(( $# > 2 ? 2 : $# ))
counts=("$@")
[ ${#counts[@]} -eq 0 ] && counts=(1 5 10 20 40)
read -r -a methods <<< "${METHODS:-rbpf segslam}"
bin=${LOOKAHEAD:-build/lookahead}
mkdir -p "$out"
# Seeds outer: an interrupted study still has every particle count.
for seed in $(seq 1 "$runs"); do
  for n in "${counts[@]}"; do
    for m in "${methods[@]}"; do
      dir="$out/$m-p$n-s$seed"
      [ -f "$dir/run.json" ] && continue  # resumable
      echo "$m, particles $n, seed $seed"
      extra=()
      [ "$m" = segslam ] && read -r -a extra <<< "${SEGSLAM_ARGS:-}"
      "$bin" slam3d garage --method "$m" --particles "$n" --seed "$seed" --data-seed 1 --map-samples 1 \
        "${extra[@]}" --out "$dir" > "$dir.log" 2>&1
    done
  done
done
python3 - "$out" "$(git rev-parse --short HEAD)" "$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)" <<'PY'
import glob, json, os, statistics as st, sys
out, commit, cpu = sys.argv[1:4]
rows = {}
for f in glob.glob(os.path.join(out, '*p*-s*/run.json')):
    j = json.load(open(f))
    rows.setdefault((j.get('method', 'rbpf'), j['particles']), []).append(j)
lines = ['| method | particles | runs | final error mean [m] | std [m] | under 1 m | run time median [s] | mean [s] | segmentations / matches (mean) | unique bytes / map | all maps / N |',
         '|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|']
summary = {'commit': commit, 'cpu': cpu, 'rows': []}
sd = lambda v: st.stdev(v) if len(v) > 1 else float('nan')
for (m, n) in sorted(rows, key=lambda k: (k[1], k[0])):
    r = rows[(m, n)]
    e = [x['final_position_error_m'] for x in r]
    t = [x['wall_time_s'] for x in r]
    u = st.mean(x['memory']['mean_unique_bytes_per_map'] for x in r)
    d = st.mean(x['memory']['distinct_bytes_per_particle'] for x in r)
    sm = f"{st.mean(x['segmentations'] for x in r):.0f} / {st.mean(x['matches'] for x in r):.0f}" if m == 'segslam' else '-'
    under = sum(1 for v in e if v < 1.0)
    lines.append(f'| {m} | {n} | {len(r)} | {st.mean(e):.2f} | {sd(e):.2f} | {under}/{len(r)} | {st.median(t):.1f} | {st.mean(t):.1f} | {sm} | {u/1e6:.2f} MB | {d/1e6:.2f} MB |')
    summary['rows'].append({'method': m, 'particles': n, 'runs': len(r), 'seeds': [x['seed'] for x in r],
                            'errors_m': e, 'times_s': t})
first = rows[min(rows, key=lambda k: k[1])][0] if rows else {}
dr = first.get('dead_reckoning_final_error_m', float('nan'))
length = first.get('path_length_m', float('nan'))
head = f'Garage loop ({length:.0f} m), dead-reckoning final error {dr:.2f} m; commit {commit}; {cpu}\n\n'
open(os.path.join(out, 'summary.md'), 'w').write(head + '\n'.join(lines) + '\n')
for k in ('configuration_yaml', 'provenance'):
    for (m, n), r in rows.items():
        if k in r[0]: summary[k] = r[0][k]
json.dump(summary, open(os.path.join(out, 'summary.json'), 'w'), indent=2)
print(head + '\n'.join(lines))
PY
