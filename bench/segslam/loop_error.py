#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# Final position error of a run on a one-loop log (SegSLAM paper, sec. 5.2 / Table II):
# the estimated pose of the last scan relative to the first, against the same relative pose
# of the reference (truth) trajectory: | (est_0^-1 est_T).xy - (ref_0^-1 ref_T).xy |.
# usage: loop_error.py TRAJECTORY.txt TRUTH.log [RUN.json]   (TRUTH: VERTEX2 lines, one per scan)
# With RUN.json the last pose is its `final_estimate`, the weighted mean of the particles (the
# paper's Table II measure: "final particle filter pose (calculated as the weighted mean of the
# particle cloud)"), instead of the trajectory's (the best particle's) last pose; the first
# pose is the trajectory's either way (every particle starts there).
import json, math, sys

def rel(a, b):
    dx, dy = b[0] - a[0], b[1] - a[1]
    c, s = math.cos(a[2]), math.sin(a[2])
    return (c * dx + s * dy, -s * dx + c * dy)

est = [tuple(map(float, l.split()[1:4])) for l in open(sys.argv[1]) if l.strip() and not l.startswith('#')]
ref = [tuple(map(float, l.split()[2:5])) for l in open(sys.argv[2]) if l.startswith('VERTEX2')]
if len(est) != len(ref):
    sys.exit(f"{sys.argv[1]}: {len(est)} poses, {sys.argv[2]}: {len(ref)} poses")
last = tuple(json.load(open(sys.argv[3]))['final_estimate']) if len(sys.argv) > 3 else est[-1]
e, r = rel(est[0], last), rel(ref[0], ref[-1])
print(f"{math.hypot(e[0] - r[0], e[1] - r[1]):.4f}")
