#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The README's RBPF-next-to-SegSLAM table from a garage_loop.sh output folder: per particle
count, error mean / std and runs under 1 m of both methods, median run times, and the median
over seeds of SegSLAM's time over the RBPF's of the same seed (pairs ran back to back).
With --json FILE also every pair's errors, times and SegSLAM's searches (match_attempts,
wide_match_attempts, matching_thread_s) in FILE.

usage: bench/seg3d/pair_table.py OUT [--json FILE]
"""
import glob
import json
import os
import statistics as st
import sys


def runs(out):
    r = {}
    for f in glob.glob(os.path.join(out, '*p*-s*/run.json')):
        j = json.load(open(f))
        r[(j.get('method', 'rbpf'), j['particles'], j['seed'])] = j
    return r


def main(out, json_file=None):
    r = runs(out)
    pairs = []
    print('| particles | runs | RBPF error mean / std [m] | SegSLAM error mean / std [m] | runs under 1 m RBPF / SegSLAM '
          '| RBPF time median [s] | SegSLAM time median [s] | time ratio SegSLAM / RBPF (median of pairs) '
          '| SegSLAM segmentations / matches (mean) |')
    print('|---:|---:|---|---|---|---:|---:|---:|---|')
    for n in sorted({k[1] for k in r}):
        seeds = sorted(s for (m, p, s) in r if m == 'segslam' and p == n and ('rbpf', n, s) in r)
        if not seeds:
            continue
        a = [r[('rbpf', n, s)] for s in seeds]
        b = [r[('segslam', n, s)] for s in seeds]
        ea = [x['final_position_error_m'] for x in a]
        eb = [x['final_position_error_m'] for x in b]
        sd = lambda v: st.stdev(v) if len(v) > 1 else float('nan')
        ratio = st.median(y['wall_time_s'] / x['wall_time_s'] for x, y in zip(a, b))
        keys = ('match_attempts', 'wide_match_attempts', 'matching_thread_s', 'wide_matching_thread_s', 'matches')
        pairs += [{'particles': n, 'seed': s, 'rbpf_error_m': x['final_position_error_m'],
                   'segslam_error_m': y['final_position_error_m'], 'rbpf_time_s': x['wall_time_s'],
                   'segslam_time_s': y['wall_time_s'], **{k: y.get(k) for k in keys}}
                  for s, x, y in zip(seeds, a, b)]
        print(f"| {n} | {len(seeds)} | {st.mean(ea):.2f} / {sd(ea):.2f} | {st.mean(eb):.2f} / {sd(eb):.2f} | "
              f"{sum(e < 1 for e in ea)} / {sum(e < 1 for e in eb)} | {st.median(x['wall_time_s'] for x in a):.1f} | "
              f"{st.median(x['wall_time_s'] for x in b):.1f} | {ratio:.2f} | "
              f"{st.mean(x['segmentations'] for x in b):.0f} / {st.mean(x['matches'] for x in b):.0f} |")


    if json_file:
        with open(json_file, 'w') as f:
            json.dump({'pairs': pairs}, f, indent=1)


if __name__ == '__main__':
    if len(sys.argv) not in (2, 4) or (len(sys.argv) == 4 and sys.argv[2] != '--json'):
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[3] if len(sys.argv) == 4 else None)
