#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Before / after table of two SegSLAM binaries from ab_loop.sh folders: per particle count,
each side's error mean / std, runs under 1 m and per-seed errors, the median over seeds of its
time over the RBPF's of the same seed (the pair ran back to back), the median of B's time over
A's, the wide searches per run and the matching thread time. Writes OUT/summary.md and
OUT/summary.json next to printing the table.

usage: bench/seg3d/ab_table.py OUT [LABEL_A LABEL_B]
"""
import json
import os
import statistics as st
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from pair_table import runs  # noqa: E402  (run.json by method, particles, seed)




def main(out, la='A', lb='B'):
    a, b = runs(os.path.join(out, 'a')), runs(os.path.join(out, 'b'))
    head = (f'| particles | seeds | error mean / std [m] {la} / {lb} | under 1 m {la} / {lb} | per seed [m] {la} | per seed [m] {lb} '
            f'| time / RBPF (median of pairs) {la} / {lb} | {lb} time / {la} (median) | time median [s] RBPF / {la} / {lb} '
            f'| wide searches per run {la} / {lb} | matching thread [s] median {la} / {lb} |')
    lines = [head, '|---:|---|---|---|---|---|---|---:|---|---|---|']
    rows = []
    sd = lambda v: st.stdev(v) if len(v) > 1 else float('nan')
    for n in sorted({k[1] for k in a if k[0] == 'segslam'}):
        seeds = sorted(s for (m, p, s) in a if m == 'segslam' and p == n and ('segslam', n, s) in b and ('rbpf', n, s) in a)
        if not seeds:
            continue
        ra = [a[('rbpf', n, s)] for s in seeds]
        sa = [a[('segslam', n, s)] for s in seeds]
        sb = [b[('segslam', n, s)] for s in seeds]
        ea = [x['final_position_error_m'] for x in sa]
        eb = [x['final_position_error_m'] for x in sb]
        t = lambda v: [x['wall_time_s'] for x in v]
        pa = st.median(y / x for x, y in zip(t(ra), t(sa)))
        pb = st.median(y / x for x, y in zip(t(ra), t(sb)))
        ba = st.median(y / x for x, y in zip(t(sa), t(sb)))
        wa = [x.get('wide_match_attempts', 0) for x in sa]
        wb = [x.get('wide_match_attempts', 0) for x in sb]
        ma = st.median(x['matching_thread_s'] for x in sa)
        mb = st.median(x['matching_thread_s'] for x in sb)
        fmt = lambda v: ', '.join(f'{e:.2f}' for e in v)
        lines.append(f'| {n} | {seeds[0]}-{seeds[-1]} | {st.mean(ea):.2f} / {sd(ea):.2f}, {st.mean(eb):.2f} / {sd(eb):.2f} | '
                     f'{sum(e < 1 for e in ea)}/{len(ea)} / {sum(e < 1 for e in eb)}/{len(eb)} | {fmt(ea)} | {fmt(eb)} | '
                     f'{pa:.2f} / {pb:.2f} | {ba:.2f} | {st.median(t(ra)):.1f} / {st.median(t(sa)):.1f} / {st.median(t(sb)):.1f} | '
                     f'{min(wa)}-{max(wa)} / {min(wb)}-{max(wb)} | {ma:.1f} / {mb:.1f} |')
        rows.append({'particles': n, 'seeds': seeds, 'errors_a_m': ea, 'errors_b_m': eb, 'rbpf_times_s': t(ra),
                     'times_a_s': t(sa), 'times_b_s': t(sb), 'ratio_a_rbpf_median': pa, 'ratio_b_rbpf_median': pb,
                     'ratio_b_a_median': ba, 'wide_searches_a': wa, 'wide_searches_b': wb,
                     'matching_thread_a_s': [x['matching_thread_s'] for x in sa],
                     'matching_thread_b_s': [x['matching_thread_s'] for x in sb],
                     'wide_matching_thread_b_s': [x.get('wide_matching_thread_s') for x in sb]})
    text = '\n'.join(lines) + '\n'
    print(text, end='')
    open(os.path.join(out, 'summary.md'), 'w').write(text)
    json.dump({'a': la, 'b': lb, 'rows': rows}, open(os.path.join(out, 'summary.json'), 'w'), indent=2)


if __name__ == '__main__':
    if len(sys.argv) not in (2, 4):
        sys.exit(__doc__)
    main(*sys.argv[1:])
