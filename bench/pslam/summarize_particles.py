#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Table of bench/pslam/particles_study.sh: P-SLAM at 40 particles against the RBPF at 40 and
200, per log and particle step, from OUT/runs.tsv.

Per cell: mean +- std over the runs (odometry seeds x filter seeds) of the Kuemmerle translational error, the
rotational error and the KL divergence from the 1000-particle map; then the paired
differences (same odometry log and filter seed) P-SLAM 40 - RBPF 40 and P-SLAM 40 - RBPF 200 with a paired
t-test.
"""
import csv
import pathlib
import statistics
import sys

sys.path.insert(0, str(pathlib.Path(__file__).parent))
from summarize_corridor import mean_std, paired_t  # noqa: E402

FILTERS = ["rbpf 40", "pslam 40", "pslam-paper 40", "rbpf 200"]


def fmt(xs, digits=3):
    m, s = mean_std(xs)
    return f"{m:.{digits}f} +- {s:.{digits}f}"


def main(path):
    rows = list(csv.DictReader(open(path), delimiter="\t"))
    cells = {}
    for r in rows:
        run = (int(r["odometry_seed"]), int(r.get("filter_seed") or 1))
        cells.setdefault((r["log"], r["proposal"]), {}).setdefault(r["filter"], {})[run] = r
    print("| log | particle step | filter | runs | relative error m | rot. deg | KL from 1000-particle map [nats] "
          "| wall s (median) | requests / hypotheses / used / rejected (sum) |")
    print("|---|---|---|---|---|---|---|---|---|")
    for (log, proposal), by_filter in cells.items():
        for f in FILTERS:
            runs = by_filter.get(f, {})
            if not runs:
                continue
            rs = list(runs.values())
            pred = "-"
            if f.startswith("pslam"):
                pred = " / ".join(str(sum(int(r[k]) for r in rs)) for k in ("requests", "hypotheses", "used", "rejected"))
            print(f"| {log} | {proposal} | {f} | {len(rs)} | {fmt([float(r['trans_mean_m']) for r in rs])} | "
                  f"{fmt([float(r['rot_mean_deg']) for r in rs], 2)} | {fmt([float(r['kl_nats']) for r in rs], 0)} | "
                  f"{statistics.median(float(r['wall_s']) for r in rs):.1f} | {pred} |")
    print("\nPaired by odometry log and filter seed (P-SLAM minus the RBPF), t-test:\n")
    print("| log | particle step | pair | runs | error difference m (t, p) | KL difference nats (t, p) |")
    print("|---|---|---|---|---|---|")
    for (log, proposal), by_filter in cells.items():
        for mine, other in (("pslam 40", "rbpf 40"), ("pslam 40", "rbpf 200"), ("pslam-paper 40", "rbpf 40"),
                            ("pslam-paper 40", "rbpf 200")):
            pslam, base = by_filter.get(mine, {}), by_filter.get(other, {})
            seeds = sorted(set(pslam) & set(base))
            if len(seeds) < 2:
                continue
            out = []
            for key in ("trans_mean_m", "kl_nats"):
                d = [float(pslam[s][key]) - float(base[s][key]) for s in seeds]
                t, p = paired_t(d)
                out.append(f"{statistics.mean(d):+.4g} (t = {t:.2f}, p = {p:.2f})")
            print(f"| {log} | {proposal} | {mine} - {other} | {len(seeds)} | {out[0]} | {out[1]} |")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "out/bench/pslam_particles/runs.tsv")
