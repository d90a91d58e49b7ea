#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# Errors of a run on the raw MIT CSAIL log against the paired reference poses (csail_truth.py):
#  - final: the loop-closure error of SegSLAM sec. 5.2 (Table II), the pose of the last paired
#    scan relative to the first, against the same relative pose of the reference:
#    | (est_0^-1 est_T).xy - (ref_0^-1 ref_T).xy | (the robot ends 0.7 m from its start);
#  - local: the mean translation error of the relative poses of paired scans K = 20 apart
#    (about 18 m of travel), the relative error of Kuemmerle et al. 2009 at one scale.
# usage: csail_error.py TRAJECTORY.txt TRUTH.txt   -> "final local"
import math, sys

def rel(a, b):
    dx, dy = b[0] - a[0], b[1] - a[1]
    c, s = math.cos(a[2]), math.sin(a[2])
    return (c * dx + s * dy, -s * dx + c * dy)

est = [tuple(map(float, l.split()[1:4])) for l in open(sys.argv[1]) if l.strip() and not l.startswith('#')]
ref = [(int(l.split()[0]), tuple(map(float, l.split()[1:4]))) for l in open(sys.argv[2]) if l.strip()]
if ref[-1][0] >= len(est):
    sys.exit(f"{sys.argv[1]}: {len(est)} poses, the reference needs scan {ref[-1][0]}")

def error(a, b):
    e, r = rel(est[a[0]], est[b[0]]), rel(a[1], b[1])
    return math.hypot(e[0] - r[0], e[1] - r[1])

K = 20
local = [error(a, b) for a, b in zip(ref, ref[K:])]
print(f"{error(ref[0], ref[-1]):.4f} {sum(local) / len(local):.4f}")
