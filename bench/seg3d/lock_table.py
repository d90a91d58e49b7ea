#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The README's locking table from a lock_pairs.sh output folder: per particle count, the RBPF,
SegSLAM and SegSLAM with locking and merging (config/segslam/locking.yaml) side by side:
final error mean / std and runs under 1 m, median run times, the median over seeds of each
SegSLAM's time over the RBPF's of the same seed (run just before), what locking did (means
per run) and memory. Writes OUT/lock_summary.json with every run's numbers.

usage: bench/seg3d/lock_table.py OUT
"""
import json
import os
import statistics as st
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from pair_table import runs  # noqa: E402  (run.json by method, particles, seed)




def main(out):
    off, on = runs(os.path.join(out, 'off')), runs(os.path.join(out, 'on'))
    sd = lambda v: st.stdev(v) if len(v) > 1 else float('nan')
    err = lambda rs: [x['final_position_error_m'] for x in rs]
    summary = {'rows': []}
    print('| particles | seeds | error mean / std [m] RBPF / SegSLAM / + locking | runs under 1 m | '
          'time median [s] RBPF / SegSLAM / + locking | time ratio to RBPF (median of pairs) SegSLAM / + locking | '
          '+ locking / SegSLAM (median of pairs) | locked / merged / locked particle updates (mean) | '
          'submaps with maps / live (mean) SegSLAM, + locking | peak MB (median) RBPF / SegSLAM / + locking | '
          'all maps / N [MB] (mean) RBPF / SegSLAM / + locking |')
    print('|---:|---:|---|---|---|---|---:|---|---|---|---|')
    for n in sorted({k[1] for k in on}):
        seeds = sorted(s for (m, p, s) in on if m == 'segslam' and p == n
                       and ('rbpf', n, s) in off and ('segslam', n, s) in off)
        if not seeds:
            continue
        a = [off[('rbpf', n, s)] for s in seeds]
        b = [off[('segslam', n, s)] for s in seeds]
        c = [on[('segslam', n, s)] for s in seeds]
        t = lambda rs: [x['wall_time_s'] for x in rs]
        ratio = lambda xs, ys: st.median(y / x for x, y in zip(t(xs), t(ys)))
        mean = lambda rs, k: st.mean(x.get(k, 0) for x in rs)
        mb = lambda rs: st.mean(x['memory']['distinct_bytes_per_particle'] for x in rs) / 1e6
        print(f"| {n} | {len(seeds)} | {st.mean(err(a)):.2f} / {sd(err(a)):.2f}, {st.mean(err(b)):.2f} / {sd(err(b)):.2f}, "
              f"{st.mean(err(c)):.2f} / {sd(err(c)):.2f} | "
              f"{sum(e < 1 for e in err(a))} / {sum(e < 1 for e in err(b))} / {sum(e < 1 for e in err(c))} | "
              f"{st.median(t(a)):.1f} / {st.median(t(b)):.1f} / {st.median(t(c)):.1f} | "
              f"{ratio(a, b):.2f} / {ratio(a, c):.2f} | {ratio(b, c):.2f} | "
              f"{mean(c, 'locked_submaps'):.0f} / {mean(c, 'merged_submaps'):.0f} / {mean(c, 'locked_particle_updates'):.0f} | "
              f"{mean(b, 'submaps_with_maps'):.0f} / {mean(b, 'live_submaps'):.0f}, "
              f"{mean(c, 'submaps_with_maps'):.0f} / {mean(c, 'live_submaps'):.0f} | "
              f"{st.median(x['peak_memory_mb'] for x in a):.0f} / {st.median(x['peak_memory_mb'] for x in b):.0f} / "
              f"{st.median(x['peak_memory_mb'] for x in c):.0f} | {mb(a):.2f} / {mb(b):.2f} / {mb(c):.2f} |")
        summary['rows'].append({
            'particles': n, 'seeds': seeds,
            'errors_m': {'rbpf': err(a), 'segslam': err(b), 'segslam_locking': err(c)},
            'times_s': {'rbpf': t(a), 'segslam': t(b), 'segslam_locking': t(c)},
            'matching_thread_s': {'segslam': [x['matching_thread_s'] for x in b],
                                  'segslam_locking': [x['matching_thread_s'] for x in c]},
            'matches': {'segslam': [x['matches'] for x in b], 'segslam_locking': [x['matches'] for x in c]},
            'locked_submaps': [x['locked_submaps'] for x in c], 'merged_submaps': [x['merged_submaps'] for x in c],
            'locked_particle_updates': [x['locked_particle_updates'] for x in c],
            'submaps_with_maps': {'segslam': [x['submaps_with_maps'] for x in b],
                                  'segslam_locking': [x['submaps_with_maps'] for x in c]},
            'live_submaps': {'segslam': [x['live_submaps'] for x in b], 'segslam_locking': [x['live_submaps'] for x in c]},
            'peak_memory_mb': {'rbpf': [x['peak_memory_mb'] for x in a], 'segslam': [x['peak_memory_mb'] for x in b],
                               'segslam_locking': [x['peak_memory_mb'] for x in c]}})
    json.dump(summary, open(os.path.join(out, 'lock_summary.json'), 'w'), indent=1)


if __name__ == '__main__':
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
