#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# What SegSLAM 3D adds to the 3D RBPF's time on the garage loop: the RBPF and SegSLAM with its
# defaults (OUT/base), SegSLAM that never segments, so one submap (eq. 13-14 bound 1e6, eq. 17
# off; OUT/noseg), and SegSLAM whose segments are never re-entered (min_separation_s 1e6, the
# wide stage off; OUT/nomatch), each through bench/seg3d/garage_loop.sh (resumable), then the
# filter time over the RBPF's of the same seed and count (median over the seeds).
#
# usage: bench/seg3d/garage_floors.sh [OUT=out/garage_floors] [RUNS=3] [COUNTS...=20 40 100]
#   LOOKAHEAD=path/to/lookahead as for garage_loop.sh.
set -euo pipefail
cd "$(dirname "$0")/../.."
out=${1:-out/garage_floors}
runs=${2:-3}
shift $(( $# > 2 ? 2 : $# ))
counts=("$@")
[ ${#counts[@]} -eq 0 ] && counts=(20 40 100)
[[ $runs =~ ^[1-9][0-9]*$ ]] || { echo "garage_floors.sh: RUNS must be a positive integer, got '$runs'" >&2; exit 1; }
mkdir -p "$out"
printf 'segmentation:\n  max_motion_error: 1000000\n  predictive_threshold: 0\n' > "$out/noseg3d.yaml"
printf 'matching:\n  min_separation_s: 1000000\n' > "$out/nomatch3d.yaml"
METHODS="rbpf segslam" bench/seg3d/garage_loop.sh "$out/base" "$runs" "${counts[@]}" > /dev/null
METHODS=segslam SEGSLAM_ARGS="--segslam-config $out/noseg3d.yaml" \
  bench/seg3d/garage_loop.sh "$out/noseg" "$runs" "${counts[@]}" > /dev/null
METHODS=segslam SEGSLAM_ARGS="--segslam-config $out/nomatch3d.yaml --wide-reentry-radius 0" \
  bench/seg3d/garage_loop.sh "$out/nomatch" "$runs" "${counts[@]}" > /dev/null
python3 - "$out" "$runs" "${counts[@]}" <<'PY'
import json, os, statistics as st, sys
out, runs, counts = sys.argv[1], int(sys.argv[2]), [int(c) for c in sys.argv[3:]]
def run(d):
    with open(os.path.join(out, d, 'run.json')) as f:
        return json.load(f)
print("| particles | one submap | segments, no re-entries | SegSLAM | SegSLAM final m (median) | RBPF final m (median) |")
print("|---|---|---|---|---|---|")
for n in counts:
    cells = []
    for variant in ('noseg', 'nomatch', 'base'):
        ratios = [run(f"{variant}/segslam-p{n}-s{s}")['wall_time_s'] / run(f"base/p{n}-s{s}")['wall_time_s']
                  for s in range(1, runs + 1)]
        cells.append(f"{st.median(ratios):.2f}")
    seg = st.median(run(f"base/segslam-p{n}-s{s}")['final_position_error_m'] for s in range(1, runs + 1))
    rbpf = st.median(run(f"base/p{n}-s{s}")['final_position_error_m'] for s in range(1, runs + 1))
    print(f"| {n} | {' | '.join(cells)} | {seg:.2f} | {rbpf:.2f} |")
print()
print("(filter wall time over the 3D RBPF's of the same seed and count, median over the seeds)")
PY
