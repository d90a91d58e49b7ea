#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Checks SegSLAM 3D's re-entries against ground truth: for each run.json (lookahead slam3d
garage --method segslam), the matches offered to the particles and taken, how many were wrong
(claimed pose more than 0.5 m or 0.05 rad from the truth, relative to the candidate's nearest
path pose), and the match scores of the right and the wrong ones.

usage: bench/seg3d/match_truth.py RUN_DIR_OR_JSON...
"""
import json
import os
import statistics as st
import sys


def wrong(e):
    return e['truth_position_error_m'] > 0.5 or abs(e['truth_yaw_error_rad']) > 0.05


def quartiles(v):
    if not v:
        return '-'
    v = sorted(v)
    return ' / '.join(f'{v[int(p * (len(v) - 1))]:.3f}' for p in (0.25, 0.5, 0.75))


def main(paths):
    offers = []
    print('| run | final error [m] | matches taken | of them wrong | offered | of them wrong |')
    print('|---|---:|---:|---:|---:|---:|')
    for p in paths:
        f = os.path.join(p, 'run.json') if os.path.isdir(p) else p
        if not f.endswith('.json'):
            continue  # e.g. the run's .log next to its folder
        j = json.load(open(f))
        o = j.get('match_offers', [])
        taken = [e for e in o if e['chosen']]
        offers += o
        print(f"| {os.path.basename(os.path.dirname(f))} | {j['final_position_error_m']:.2f} | {len(taken)} | "
              f"{sum(map(wrong, taken))} | {len(o)} | {sum(map(wrong, o))} |")
    print('\nscores of the offers, quartiles (right | wrong):')
    for k in ('icp_error_m', 'all_points_error_m', 'structure_error_m', 'structure_inlier_ratio',
              'structure_free_ratio', 'weight'):
        if offers and k in offers[0]:
            r = [e[k] for e in offers if not wrong(e)]
            w = [e[k] for e in offers if wrong(e)]
            print(f'  {k:24s} {quartiles(r)}  |  {quartiles(w)}   ({len(r)} right, {len(w)} wrong)')


if __name__ == '__main__':
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    main(sys.argv[1:])
