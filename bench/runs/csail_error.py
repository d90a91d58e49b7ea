#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# Errors of a run on the raw MIT CSAIL log against the paired reference poses (csail_truth.py):
#  - final: the loop-closure error of SegSLAM sec. 5.2 (Table II), the pose of the last paired
#    scan relative to the first, against the same relative pose of the reference:
#    | (est_0^-1 est_T).xy - (ref_0^-1 ref_T).xy | (the robot ends 0.7 m from its start);
#  - local: the mean translation error of the relative poses of paired scans K = 20 apart
#    (about 18 m of travel), the relative error of Kuemmerle et al. 2009 at one scale.
#  - global (with --global, a third column): the RMSE of the paired scans' positions after the
#    rigid motion that best aligns them with the reference (absolute trajectory error): how
#    consistent the whole path, and a map drawn along it, is.
# usage: csail_error.py TRAJECTORY.txt TRUTH.txt [--global]   -> "final local [global]"
import math, sys

if len(sys.argv) not in (3, 4) or (len(sys.argv) == 4 and sys.argv[3] != '--global'):
    sys.exit("usage: csail_error.py TRAJECTORY.txt TRUTH.txt [--global]")

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

def aligned_rmse():
    # Closed-form 2D rigid alignment (least squares rotation and translation) of est onto ref.
    p = [est[i][:2] for i, _ in ref]
    q = [r[:2] for _, r in ref]
    n = len(p)
    pc = (sum(a[0] for a in p) / n, sum(a[1] for a in p) / n)
    qc = (sum(b[0] for b in q) / n, sum(b[1] for b in q) / n)
    sxx = sum((a[0] - pc[0]) * (b[0] - qc[0]) + (a[1] - pc[1]) * (b[1] - qc[1]) for a, b in zip(p, q))
    sxy = sum((a[0] - pc[0]) * (b[1] - qc[1]) - (a[1] - pc[1]) * (b[0] - qc[0]) for a, b in zip(p, q))
    th = math.atan2(sxy, sxx)
    c, s = math.cos(th), math.sin(th)
    err = 0.0
    for a, b in zip(p, q):
        x, y = a[0] - pc[0], a[1] - pc[1]
        err += (c * x - s * y + qc[0] - b[0]) ** 2 + (s * x + c * y + qc[1] - b[1]) ** 2
    return math.sqrt(err / n)

line = f"{error(ref[0], ref[-1]):.4f} {sum(local) / len(local):.4f}"
print(line + (f" {aligned_rmse():.4f}" if len(sys.argv) == 4 else ""))
