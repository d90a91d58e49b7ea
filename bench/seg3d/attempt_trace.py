#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Traces SegSLAM 3D's re-entry attempts against ground truth: for each run.json written with
SPDLOG_LEVEL=debug (lookahead slam3d garage --method segslam), the candidates a particle
considered while the robot TRULY was within REACH m of where the candidate had been mapped
(same deck), i.e. where a right re-entry was possible, and what became of them: winnowed by
proximity (far / unobserved), not among the nearest, matched and rejected (why), or offered.
With the map sample's guess error against the truth and the coarse search's scores.

usage: bench/seg3d/attempt_trace.py [--reach M] [--from SWEEP] [--list] RUN_DIR_OR_JSON...
"""
import argparse
import collections
import json
import os
import statistics as st


def quart(v):
    if not v:
        return '-'
    v = sorted(v)
    return ' / '.join(f'{v[int(p * (len(v) - 1))]:.2f}' for p in (0.25, 0.5, 0.75))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--reach', type=float, default=4.0, help='robot truly this near the candidate path [m]')
    ap.add_argument('--from', dest='first', type=int, default=0, help='only attempts from this sweep on')
    ap.add_argument('--list', action='store_true', help='print every such attempt')
    ap.add_argument('runs', nargs='+')
    a = ap.parse_args()
    for p in a.runs:
        f = os.path.join(p, 'run.json') if os.path.isdir(p) else p
        if not f.endswith('.json'):
            continue
        j = json.load(open(f))
        log = j.get('match_attempt_log')
        if log is None:
            print(f'{p}: no match_attempt_log (run with SPDLOG_LEVEL=debug)')
            continue
        near = [e for e in log if (e['truth_distance_to_candidate_path_m'] or 1e9) <= a.reach and e['sweep'] >= a.first]
        print(f"\n{os.path.basename(os.path.dirname(f))}: final error {j['final_position_error_m']:.2f} m, "
              f"{j['matches']} matches; {len(log)} candidates considered, {len(near)} while the robot truly was "
              f"within {a.reach:g} m of the candidate's path (sweep >= {a.first})")
        by = collections.defaultdict(list)
        for e in near:
            by[e['outcome'] + (': ' + e['rejection'] if e['rejection'] else '')].append(e)
        for k, v in sorted(by.items()):
            print(f"  {k:28s} {len(v):4d}  guess off truth [m] {quart([e['guess_truth_position_error_m'] for e in v])}"
                  f"  [rad] {quart([abs(e['guess_truth_yaw_error_rad']) for e in v])}"
                  f"  from path [m] {quart([e['path_distance_m'] or 1e9 for e in v])}"
                  f"  coarse {quart([e['coarse_score'] for e in v])}")
        if a.list:
            for e in near:
                print(f"    sweep {e['sweep']:3d} p{e['particle']} cand {e['candidate']:3d} {e['outcome']:11s} "
                      f"{e['rejection']:17s} match {e.get('match_path_distance_m', 0):4.1f} m from path, guess {e['guess_truth_position_error_m']:5.2f} m "
                      f"{e['guess_truth_yaw_error_rad']:+.3f} rad {e.get('guess_truth_height_error_m', 0):+.2f} m z off, {e['path_distance_m'] or 1e9:5.1f} m from path "
                      f"(r {e['proximity_radius_m']:.1f}, search {e['search_radius_m']:.1f}), robot truly "
                      f"{e['truth_distance_to_candidate_path_m']:.1f} m, coarse {e['guess_score']:.2f}->{e['coarse_score']:.2f}")


if __name__ == '__main__':
    main()
