#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Utility's information gain, disc against line of sight, per world of a study.

Reads the committed results of a study (nearest + utility with the disc gain, measured
before line of sight) and a re-run of its utility runs with line of sight, and prints a
markdown table: time and path to 95 % (mean +- std over the runs that reached it, and how
many did) for nearest, utility-disc and utility-line-of-sight, with Welch's t-test (two
sided, Student t) of line of sight against each where both have two runs or more.

  bench/exploration/compare_gain.py OLD_results.csv NEW_results.csv [NEW_STRATEGY]

NEW_STRATEGY (default utility) names the strategy of the re-run, e.g. predictive-utility.
"""
import csv
import math
import sys


def betacf(a, b, x):
    # Continued fraction of the regularised incomplete beta function (modified Lentz).
    tiny = 1e-300
    c, d = 1.0, 1.0 - (a + b) * x / (a + 1)
    d = 1.0 / (d if abs(d) > tiny else tiny)
    h = d
    for m in range(1, 300):
        for num in (m * (b - m) * x / ((a + 2 * m - 1) * (a + 2 * m)),
                    -(a + m) * (a + b + m) * x / ((a + 2 * m) * (a + 2 * m + 1))):
            d = 1.0 + num * d
            d = 1.0 / (d if abs(d) > tiny else tiny)
            c = 1.0 + num / c
            c = c if abs(c) > tiny else tiny
            h *= d * c
        if abs(d * c - 1.0) < 1e-12:
            break
    return h


def betainc(a, b, x):
    if x <= 0 or x >= 1:
        return max(0.0, min(1.0, x))
    front = math.exp(math.lgamma(a + b) - math.lgamma(a) - math.lgamma(b) + a * math.log(x) + b * math.log(1 - x))
    if x < (a + 1) / (a + b + 2):
        return front * betacf(a, b, x) / a
    return 1.0 - front * betacf(b, a, 1 - x) / b


def welch_p(xs, ys):
    if len(xs) < 2 or len(ys) < 2:
        return None
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    vx = sum((v - mx) ** 2 for v in xs) / (len(xs) - 1) / len(xs)
    vy = sum((v - my) ** 2 for v in ys) / (len(ys) - 1) / len(ys)
    if vx + vy == 0:
        return 1.0 if mx == my else 0.0
    t = (mx - my) / math.sqrt(vx + vy)
    df = (vx + vy) ** 2 / (vx ** 2 / (len(xs) - 1) + vy ** 2 / (len(ys) - 1))
    return betainc(df / 2, 0.5, df / (df + t * t))


def load(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def values(rows, world, strategy, key):
    return [float(r[key]) for r in rows if r['world'] == world and r['strategy'] == strategy and r[key]]


def cell(rows, world, strategy):
    n = sum(1 for r in rows if r['world'] == world and r['strategy'] == strategy)
    t = values(rows, world, strategy, 'time_to_95_s')
    p = values(rows, world, strategy, 'path_to_95_m')
    if not t:
        cov = [float(r['coverage']) for r in rows if r['world'] == world and r['strategy'] == strategy]
        return f"0/{n} ({max(cov) * 100:.1f} %)"
    if len(t) == 1:
        return f"{t[0]:.0f} s / {p[0]:.0f} m" + ("" if n == 1 else f" ({len(t)}/{n})")
    sd = lambda v: math.sqrt(sum((x - sum(v) / len(v)) ** 2 for x in v) / (len(v) - 1))
    return f"{sum(t) / len(t):.0f} +- {sd(t):.0f} s / {sum(p) / len(p):.0f} m" + ("" if len(t) == n else f" ({len(t)}/{n})")


def fmt_p(p):
    return "-" if p is None else f"{p:.2f}"


def main():
    old, new = load(sys.argv[1]), load(sys.argv[2])
    strategy = sys.argv[3] if len(sys.argv) > 3 else 'utility'
    worlds = list(dict.fromkeys(r['world'] for r in new))
    print(f"| world | nearest | utility, disc gain | {strategy}, line of sight | p (LOS vs nearest) | p (LOS vs disc) |")
    print("|---|---|---|---|---|---|")
    for w in worlds:
        los = values(new, w, strategy, 'time_to_95_s')
        print(f"| {w} | {cell(old, w, 'nearest')} | {cell(old, w, 'utility')} | {cell(new, w, strategy)} | "
              f"{fmt_p(welch_p(los, values(old, w, 'nearest', 'time_to_95_s')))} | "
              f"{fmt_p(welch_p(los, values(old, w, 'utility', 'time_to_95_s')))} |")
    # Geometric mean of per-run time ratios over runs that reached 95 % in both (paired by seed).
    for base in ('nearest', 'utility'):
        ratios = []
        for r in (r for r in new if r['strategy'] == strategy):
            o = [x for x in old if x['world'] == r['world'] and x['strategy'] == base and x['seed'] == r['seed']]
            if o and o[0]['time_to_95_s'] and r['time_to_95_s']:
                ratios.append(float(r['time_to_95_s']) / float(o[0]['time_to_95_s']))
        if ratios:
            g = math.exp(sum(math.log(x) for x in ratios) / len(ratios))
            faster = sum(x < 1 for x in ratios)
            print(f"\nLine of sight against {base} ({'disc' if base == 'utility' else 'same seed'}): geometric mean of the "
                  f"time-to-95 % ratios {g:.2f} over {len(ratios)} paired runs ({faster} faster, {len(ratios) - faster} slower or equal)")


if __name__ == '__main__':
    main()
