#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# Error of a trajectory of a raw CARMEN log against a corrected log of the same run
# (GMapping's .gfs.log, the Radish csail.corrected.log). The corrected logs keep only some
# scans and print their stamps too coarsely to pair by time, so each corrected scan is paired
# with the raw scan of the same ranges (printed to 2 decimals), and the trajectory's pose of
# that raw scan is looked up by its ipc stamp (the first column of trajectory.txt).
#   reference_error.py RAW.log CORRECTED.log TRAJECTORY.txt
# prints "rel_rot_mean_deg ate_rmse_m ate_max_m paired": the rotation error between
# consecutive corrected scans, and the absolute error after the least-squares SE(2) alignment.
import math
import sys


def laser_lines(path):
    """(ranges key, ipc stamp, pose) of every FLASER line, or of every ROBOTLASER1 line in a
    log without FLASER (logs that hold both repeat each scan in both)."""
    out = {'FLASER': [], 'ROBOTLASER1': []}
    for line in open(path):
        f = line.split()
        if not f:
            continue
        if f[0] == 'FLASER':
            n, first = int(f[1]), 2
            pose = f[first + n:first + n + 3]
        elif f[0] == 'ROBOTLASER1':
            n, first = int(f[8]), 9
            k = first + n
            pose = f[k + 1 + int(f[k]):][:3]
        else:
            continue
        key = ' '.join(f"{float(v):.2f}" for v in f[first:first + n])
        out[f[0]].append((key, float(f[-3]), tuple(map(float, pose))))
    return out['FLASER'] or out['ROBOTLASER1']


def main():
    if len(sys.argv) != 4:
        sys.exit("usage: reference_error.py RAW.log CORRECTED.log TRAJECTORY.txt")
    raw_path, ref_path, traj_path = sys.argv[1:]
    stamp_of = {}
    for key, stamp, _ in laser_lines(raw_path):
        stamp_of.setdefault(key, []).append(stamp)
    est = {}
    for number, line in enumerate(open(traj_path), 1):
        if line.startswith('#') or not line.strip():
            continue
        f = line.split()
        if len(f) < 4:
            sys.exit(f"{traj_path}:{number}: expected 'stamp x y theta', got '{line.strip()}'")
        est[round(float(f[0]), 4)] = tuple(map(float, f[1:4]))
    pairs = []
    for key, _, pose in laser_lines(ref_path):
        stamps = stamp_of.get(key, [])
        if len(stamps) == 1 and round(stamps[0], 4) in est:
            pairs.append((pose, est[round(stamps[0], 4)]))
    if len(pairs) < 3:
        sys.exit(f"{ref_path}: only {len(pairs)} scans paired with {raw_path} and {traj_path}")
    wrap = lambda a: (a + math.pi) % (2 * math.pi) - math.pi
    rot = [abs(wrap((b[0][2] - a[0][2]) - (b[1][2] - a[1][2]))) for a, b in zip(pairs, pairs[1:])]
    n = len(pairs)
    mr = [sum(p[0][k] for p in pairs) / n for k in (0, 1)]
    me = [sum(p[1][k] for p in pairs) / n for k in (0, 1)]
    sxx = sum((e[0] - me[0]) * (r[0] - mr[0]) + (e[1] - me[1]) * (r[1] - mr[1]) for r, e in pairs)
    sxy = sum((e[0] - me[0]) * (r[1] - mr[1]) - (e[1] - me[1]) * (r[0] - mr[0]) for r, e in pairs)
    c, s = math.cos(math.atan2(sxy, sxx)), math.sin(math.atan2(sxy, sxx))
    err = [math.hypot(c * (e[0] - me[0]) - s * (e[1] - me[1]) + mr[0] - r[0],
                      s * (e[0] - me[0]) + c * (e[1] - me[1]) + mr[1] - r[1]) for r, e in pairs]
    print("%.2f %.3f %.2f %d" % (math.degrees(sum(rot) / len(rot)),
                                 math.sqrt(sum(x * x for x in err) / n), max(err), n))


main()
