#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Loop-closure error of the 3D RBPF on the simulated garage loop against particle count
# (SegSLAM Tables II and III): the same simulated log (--data-seed 1) filtered RUNS times
# per count with filter seeds 1..RUNS. Writes OUT/summary.md and OUT/summary.json (commit,
# CPU, parameters), and every run's folder (map.bt, trajectory.png, run.json).
#
# usage: bench/seg3d/garage_loop.sh [OUT] [RUNS] [COUNTS...]
#   e.g. bench/seg3d/garage_loop.sh out/garage_loop 5 1 5 10 20 40
set -euo pipefail
out=${1:-out/garage_loop}
runs=${2:-5}
shift $(( $# > 2 ? 2 : $# ))
counts=("$@")
[ ${#counts[@]} -eq 0 ] && counts=(1 5 10 20 40)
bin=${LOOKAHEAD:-build/lookahead}
mkdir -p "$out"
# Seeds outer: an interrupted study still has every particle count.
for seed in $(seq 1 "$runs"); do
  for n in "${counts[@]}"; do
    dir="$out/p$n-s$seed"
    [ -f "$dir/run.json" ] && continue  # resumable
    echo "particles $n, seed $seed"
    "$bin" slam3d garage --method rbpf --particles "$n" --seed "$seed" --data-seed 1 --out "$dir" > "$dir.log" 2>&1
  done
done
python3 - "$out" "$(git rev-parse --short HEAD)" "$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)" <<'PY'
import glob, json, os, statistics as st, sys
out, commit, cpu = sys.argv[1:4]
rows = {}
for f in glob.glob(os.path.join(out, 'p*-s*/run.json')):
    j = json.load(open(f))
    rows.setdefault(j['particles'], []).append(j)
lines = ['| particles | runs | final error mean [m] | std [m] | run time mean [s] | std [s] | unique bytes / map | all maps / N |',
         '|---:|---:|---:|---:|---:|---:|---:|---:|']
summary = {'commit': commit, 'cpu': cpu, 'rows': []}
for n in sorted(rows):
    r = rows[n]
    e = [x['final_position_error_m'] for x in r]
    t = [x['wall_time_s'] for x in r]
    sd = lambda v: st.stdev(v) if len(v) > 1 else float('nan')
    u = st.mean(x['memory']['mean_unique_bytes_per_map'] for x in r)
    d = st.mean(x['memory']['distinct_bytes_per_particle'] for x in r)
    lines.append(f'| {n} | {len(r)} | {st.mean(e):.2f} | {sd(e):.2f} | {st.mean(t):.1f} | {sd(t):.1f} | {u/1e6:.2f} MB | {d/1e6:.2f} MB |')
    summary['rows'].append({'particles': n, 'runs': len(r), 'errors_m': e, 'times_s': t})
dr = rows[min(rows)][0]['dead_reckoning_final_error_m'] if rows else float('nan')
length = rows[min(rows)][0]['path_length_m'] if rows else float('nan')
head = f'Garage loop ({length:.0f} m), dead-reckoning final error {dr:.2f} m; commit {commit}; {cpu}\n\n'
open(os.path.join(out, 'summary.md'), 'w').write(head + '\n'.join(lines) + '\n')
summary['parameters_yaml'] = rows[min(rows)][0]['parameters_yaml'] if rows else ''
json.dump(summary, open(os.path.join(out, 'summary.json'), 'w'), indent=2)
print(head + '\n'.join(lines))
PY
