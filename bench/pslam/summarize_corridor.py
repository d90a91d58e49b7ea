#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Table of bench/pslam/corridor_study.sh: RBPF against P-SLAM on the corridor world.

Reads OUT/{rbpf,pslam}-SEED/run.json; prints mean +- std per filter, the paired difference
of P-SLAM minus RBPF per seed (same world, odometry and sensor noise), and a paired t-test.
"""
import json
import math
import pathlib
import statistics
import sys

METRICS = [("slam_position_error_mean_m", "mean position error m"),
           ("slam_position_error_final_m", "final position error m"),
           ("map_precision", "map precision"),
           ("map_recall", "map recall"),
           ("simulated_time_s", "time to 95 % s")]


def load(out):
    runs = {}
    for p in sorted(pathlib.Path(out).glob("*-*/run.json")):
        label, seed = p.parent.name.rsplit("-", 1)
        runs.setdefault(label, {})[int(seed)] = json.loads(p.read_text())
    return runs


def mean_std(xs):
    return statistics.mean(xs), (statistics.stdev(xs) if len(xs) > 1 else 0.0)


def paired_t(diffs):
    """t statistic and two-sided p of the paired differences (normal tail beyond 30 seeds)."""
    n = len(diffs)
    if n < 2:
        return float("nan"), float("nan")
    m, s = mean_std(diffs)
    if s == 0:
        return float("inf") if m else 0.0, 0.0 if m else 1.0
    t = m / (s / math.sqrt(n))
    return t, student_p(abs(t), n - 1)


def student_p(t, dof):
    """Two-sided p of Student's t: the regularized incomplete beta I_x(dof/2, 1/2)."""
    x = dof / (dof + t * t)
    a, b = dof / 2.0, 0.5
    # The continued fraction converges for x < (a + 1) / (a + b + 2); beyond, by symmetry.
    if x > (a + 1) / (a + b + 2):
        return min(1.0, 1.0 - _beta_fraction(b, a, 1.0 - x))
    return min(1.0, _beta_fraction(a, b, x))


def _beta_fraction(a, b, x):
    """I_x(a, b) by its continued fraction (Lentz), for x below the mean."""
    if x <= 0.0:
        return 0.0
    lbeta = math.lgamma(a) + math.lgamma(b) - math.lgamma(a + b)
    front = math.exp(math.log(x) * a + math.log1p(-x) * b - lbeta) / a
    f, c, d = 1.0, 1.0, 0.0
    for i in range(200):
        m = i // 2
        if i == 0:
            num = 1.0
        elif i % 2 == 0:
            num = (m * (b - m) * x) / ((a + 2 * m - 1) * (a + 2 * m))
        else:
            num = -((a + m) * (a + b + m) * x) / ((a + 2 * m) * (a + 2 * m + 1))
        d = 1.0 + num * d
        d = 1.0 / (d if abs(d) > 1e-30 else 1e-30)
        c = 1.0 + num / (c if abs(c) > 1e-30 else 1e-30)
        f *= c * d
        if abs(1.0 - c * d) < 1e-12:
            break
    return front * (f - 1.0)


def main(out):
    runs = load(out)
    rbpf, pslam = runs.get("rbpf", {}), runs.get("pslam", {})
    seeds = sorted(set(rbpf) & set(pslam))
    if not seeds:
        sys.exit(f"{out}: no seed has both an rbpf and a pslam run")
    print(f"corridor, {len(seeds)} seeds (paired: same world, odometry and sensor noise)\n")
    print("| metric | RBPF | P-SLAM | P-SLAM - RBPF (paired) | t | p |")
    print("|---|---|---|---|---|---|")
    for key, name in METRICS:
        a = [rbpf[s][key] for s in seeds]
        b = [pslam[s][key] for s in seeds]
        d = [y - x for x, y in zip(a, b)]
        t, p = paired_t(d)
        (ma, sa), (mb, sb), (md, sd) = mean_std(a), mean_std(b), mean_std(d)
        print(f"| {name} | {ma:.3f} +- {sa:.3f} | {mb:.3f} +- {sb:.3f} | {md:+.3f} +- {sd:.3f} | {t:.2f} | {p:.3f} |")
    pred = [pslam[s]["prediction"] for s in seeds]
    filt = [p["filter"] for p in pred]
    print(f"\nP-SLAM: {sum(p['requests'] for p in pred)} prediction requests, "
          f"{sum(p['hypotheses'] for p in pred)} hypotheses "
          f"(no control point {sum(p['no_control_point'] for p in pred)}, no match {sum(p['no_match'] for p in pred)}), "
          f"filter updates with a hypothesis {sum(f['predicted_updates'] for f in filt)}, "
          f"used {sum(f['used'] for f in filt)}, rejected by the hit ratio {sum(f['rejected_by_hit_ratio'] for f in filt)}; "
          f"mean Psi of the hypotheses against the world "
          f"{statistics.mean([p['mean_psi_world'] for p in pred if p['hypotheses']] or [0]):.2f}.")
    print(f"Wall time per run: RBPF {statistics.median([rbpf[s]['wall_time_s'] for s in seeds]):.1f} s, "
          f"P-SLAM {statistics.median([pslam[s]['wall_time_s'] for s in seeds]):.1f} s (medians).")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "out/bench/pslam_corridor")
