#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# Where the loop-closure error of a run comes from: the heading error the estimate already
# has early on (after the log's first turn, scan 16 by default) against the final position
# error, both relative to the first scan as in loop_error.py; one line per run, then the
# correlation over the runs.
# usage: start_heading.py TRUTH.log RUN_DIR... [--scan K]   (RUN_DIR holds trajectory.txt)
import math, sys

def rel(a, b):
    dx, dy = b[0] - a[0], b[1] - a[1]
    c, s = math.cos(a[2]), math.sin(a[2])
    return (c * dx + s * dy, -s * dx + c * dy, b[2] - a[2])

args = sys.argv[1:]
scan = 16
if '--scan' in args:
    i = args.index('--scan')
    scan = int(args[i + 1])
    del args[i:i + 2]
if len(args) < 2:
    sys.exit(__doc__ or "usage: start_heading.py TRUTH.log RUN_DIR... [--scan K]")
ref = [tuple(map(float, l.split()[2:5])) for l in open(args[0]) if l.startswith('VERTEX2')]

def error(est, k):
    e, r = rel(est[0], est[k]), rel(ref[0], ref[k])
    return math.hypot(e[0] - r[0], e[1] - r[1]), math.atan2(math.sin(e[2] - r[2]), math.cos(e[2] - r[2]))

early, final = [], []
for d in args[1:]:
    est = [tuple(map(float, l.split()[1:4])) for l in open(d + '/trajectory.txt') if l.strip() and not l.startswith('#')]
    if len(est) != len(ref):
        sys.exit(f"{d}/trajectory.txt: {len(est)} poses, {args[0]}: {len(ref)} poses")
    h, f = error(est, scan), error(est, len(est) - 1)
    early.append(abs(h[1]))
    final.append(f[0])
    print(f"{d}: scan {scan} heading error {h[1]:+.3f} rad (position {h[0]:.3f} m); final position error {f[0]:.3f} m, heading {f[1]:+.3f} rad")
if len(early) > 2:
    n = len(early)
    me, mf = sum(early) / n, sum(final) / n
    cov = sum((a - me) * (b - mf) for a, b in zip(early, final))
    norm = math.sqrt(sum((a - me) ** 2 for a in early) * sum((b - mf) ** 2 for b in final))
    print(f"correlation of |heading error at scan {scan}| with the final error over {n} runs: {cov / norm:.2f}")
