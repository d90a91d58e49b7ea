#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# Labels every re-entry SegSLAM 2D tried on the raw MIT CSAIL log against the reference: how
# far the matched pose (and the map sample's guess) lies from where the reference puts the
# robot in the candidate's frame. Reads the run's debug log (SPDLOG_LEVEL=debug lookahead slam
# ... --method segslam), the raw log (odometry per scan) and the paired reference poses
# (csail_truth.py).
#
# A submap's frame is the robot at the frame's first scan (a fresh submap starts at the
# particle's pose; the first submap is the odometry frame of scan 0), so the robot at scan k
# in it is ref(first)^-1 ref(k). Scans between paired ones are placed by odometry from the
# nearest paired scan. The offset also holds the submap's own drift between its first scan and
# the place re-entered (a metre or two for the long segments of the 2D defaults): "near"
# below 1 m is a right re-entry, "far" above 3 m a wrong one.
#
# usage: csail_match_labels.py DEBUG_LOG RAW_LOG TRUTH.txt   -> one line per distinct attempt, then a summary
import bisect, math, re, statistics, sys


def compose(a, b):
    c, s = math.cos(a[2]), math.sin(a[2])
    return (a[0] + c * b[0] - s * b[1], a[1] + s * b[0] + c * b[1], a[2] + b[2])


def inverse(a):
    c, s = math.cos(a[2]), math.sin(a[2])
    return (-c * a[0] - s * a[1], s * a[0] - c * a[1], -a[2])


def odometry(raw_log):
    out = []
    for line in open(raw_log):
        if line.startswith('FLASER'):
            f = line.split()
            n = int(f[1])
            out.append(tuple(map(float, f[2 + n + 3:2 + n + 6])))
    return out


PATTERN = re.compile(r'scan (\d+) candidate (\d+) \[(\d+)-(\d+)\] frame (\d+) guess \(([-\d.]+) ([-\d.]+) ([-\d.]+)\) '
                     r'-> \(([-\d.]+) ([-\d.]+) ([-\d.]+)\) err ([\d.]+) tau ([\d.]+) ok (\w+) w ([\d.]+)')


def main(debug_log, raw_log, truth_file):
    odom = odometry(raw_log)
    ref = {int(l.split()[0]): tuple(map(float, l.split()[1:4])) for l in open(truth_file) if l.strip()}
    paired = sorted(ref)

    def reference(scan):
        i = bisect.bisect_left(paired, scan)
        p = min((paired[j] for j in (i - 1, i) if 0 <= j < len(paired)), key=lambda q: abs(q - scan))
        return compose(ref[p], compose(inverse(odom[p]), odom[scan]))

    rows, seen = [], set()
    for line in open(debug_log):
        m = PATTERN.search(line)
        if not m:
            continue
        scan, candidate, first, last, frame = map(int, m.group(1, 2, 3, 4, 5))
        guess, pose = tuple(map(float, m.group(6, 7, 8))), tuple(map(float, m.group(9, 10, 11)))
        err, tau, ok, weight = float(m.group(12)), float(m.group(13)), m.group(14) == 'true', float(m.group(15))
        key = (scan, frame, round(pose[0], 1), round(pose[1], 1), ok)
        if key in seen:  # copies of one segment asked for the same match
            continue
        seen.add(key)
        robot = compose(inverse(reference(frame)), reference(scan))
        if frame == 0:
            robot = compose(odom[0], robot)
        off = math.hypot(pose[0] - robot[0], pose[1] - robot[1])
        guess_off = math.hypot(guess[0] - robot[0], guess[1] - robot[1])
        rows.append((ok, err, off, guess_off))
        print(f"{scan} candidate {candidate} [{first}-{last}] frame {frame} ok {int(ok)} err {err:.3f} tau {tau:.2f} "
              f"w {weight:.3f} match_off {off:.2f} guess_off {guess_off:.2f}")
    passed = [r for r in rows if r[0]]
    near = [r for r in passed if r[2] < 1.0]
    far = [r for r in passed if r[2] > 3.0]

    def med(v):
        return f"{statistics.median(v):.3f}" if v else "-"
    print(f"# attempts {len(rows)}, passed {len(passed)}: near (< 1 m) {len(near)}, far (> 3 m) {len(far)}; "
          f"median err_ICP near {med([r[1] for r in near])} far {med([r[1] for r in far])}; "
          f"median guess offset near {med([r[3] for r in near])} far {med([r[3] for r in far])} m")


if __name__ == '__main__':
    if len(sys.argv) != 4:
        sys.exit('usage: csail_match_labels.py DEBUG_LOG RAW_LOG TRUTH.txt')
    main(*sys.argv[1:])
