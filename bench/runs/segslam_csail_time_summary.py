#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# The summary of bench/runs/segslam_csail_time.sh from its runs file: medians per particle count
# and method, and the time ratios (the median over the seeds of each seed's ratio).
#
# usage: csail_rbpf_time_summary.py RUNS.txt > SUMMARY.md
import statistics as st
import sys

if len(sys.argv) != 2:
    sys.exit("usage: csail_rbpf_time_summary.py RUNS.txt")
rows = [l.split() for l in open(sys.argv[1]) if l.strip() and not l.startswith('#')]
for k, r in enumerate(rows):
    if len(r) != 7:
        sys.exit(f"{sys.argv[1]}: run {k + 1} has {len(r)} fields, expected 7: {' '.join(r)}")
cell = {}
for k, (m, n, s, wall, filt, err, mb) in enumerate(rows):
    try:
        cell.setdefault((m, int(n)), {})[int(s)] = (float(wall), None if filt == '-' else float(filt), float(err), int(mb))
    except ValueError as e:
        sys.exit(f"{sys.argv[1]}: run {k + 1}: {e}")
def med(xs): return st.median(xs) if xs else float('nan')
def ratio(a, b, k):
    both = sorted(set(cell.get(a, {})) & set(cell.get(b, {})))
    return med([cell[a][s][k] / cell[b][s][k] for s in both])
print("| particles | method | runs | process s (median) | filter s (median) | final error m (median) | peak MB (median) |")
print("|---|---|---|---|---|---|---|")
for n in sorted({n for _, n in cell}):
    for m in ('segslam', 'segslam-nomatch', 'segslam-noseg', 'rbpf', 'mrpt'):
        c = cell.get((m, n))
        if not c: continue
        v = list(c.values())
        filt = [x[1] for x in v if x[1] is not None]
        print(f"| {n} | {m} | {len(v)} | {med([x[0] for x in v]):.1f} | {med(filt):.2f} | {med([x[2] for x in v]):.2f} | {med([x[3] for x in v]):.0f} |" if filt else
              f"| {n} | {m} | {len(v)} | {med([x[0] for x in v]):.1f} | - | {med([x[2] for x in v]):.2f} | {med([x[3] for x in v]):.0f} |")
print()
print("| particles | SegSLAM / our RBPF, filter time | SegSLAM / our RBPF, process time | SegSLAM / MRPT rbpf-slam, process time | no re-entries / our RBPF, filter time | one submap / our RBPF, filter time |")
print("|---|---|---|---|---|---|")
for n in sorted({n for _, n in cell}):
    r = lambda a, b, k: f"{ratio((a, n), (b, n), k):.2f}" if (a, n) in cell and (b, n) in cell else "-"
    print(f"| {n} | {r('segslam', 'rbpf', 1)} | {r('segslam', 'rbpf', 0)} | {r('segslam', 'mrpt', 0)} | {r('segslam-nomatch', 'rbpf', 1)} | {r('segslam-noseg', 'rbpf', 1)} |")
print()
print("(ratios: the median over the seeds of each seed's ratio)")
