#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""P-SLAM reproduction 3 per plan: the four strategies of a `lookahead study` on the KTH
plans (nearest, utility, predictive, predictive-utility), each one's mission time and path
(mean over seeds; a run ends at 95 % explored, a predictive one at 95 % explored or
correctly predicted), Welch's test of predictive against nearest and of predictive-utility
against utility, the paired-by-seed ratios over all plans, and on how many plans the
prediction shortens the path by 12 % or more (the low end of the published 12-35 %).
With a second folder (the same study at an older commit), each strategy's change per plan.

  python3 bench/pslam/compare_kth.py OUT [OLD_OUT]

Standard library only (the t-test is summarize_runs.py's)."""
import os, sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from summarize_runs import load, mean_std, welch  # noqa: E402

PAIRS = (('predictive', 'nearest'), ('predictive-utility', 'utility'),
         ('predictive-utility', 'nearest'), ('utility', 'nearest'))
KEYS = (('simulated_time_s', 'time'), ('path_length_m', 'path'))


def values(runs, world, strategy, key):
    return [r[key] for r in sorted(runs.get((world, strategy), []), key=lambda r: r['seed'])]


def mean(v):
    return mean_std(v)[0]


def median(q):
    q = sorted(q)
    return q[len(q) // 2] if len(q) % 2 else (q[len(q) // 2 - 1] + q[len(q) // 2]) / 2


def change(a, b):
    """'-6.2 % (p = 0.35)': b's mean against a's, Welch p (none when every seed gave the same value)."""
    d = 100 * (mean(b) - mean(a)) / mean(a)
    if a == b: return f"{d:+.1f} % (the same values)"
    return f"{d:+.1f} % (p = {welch(b, a)[1]:.3f})"


def main(folder, old=None):
    runs = load(folder)
    worlds = sorted({w for w, _ in runs})
    print("Time / path per plan, mean of the seeds:\n")
    print("| world | nearest | utility | predictive | predictive-utility | predictive vs nearest: time, path (Welch) "
          "| predictive-utility vs utility: time, path (Welch) |")
    print("|---|---|---|---|---|---|---|")
    for w in worlds:
        cells = [f"{mean(values(runs, w, s, 'simulated_time_s')):.0f} s / {mean(values(runs, w, s, 'path_length_m')):.0f} m"
                 for s in ('nearest', 'utility', 'predictive', 'predictive-utility')]
        cmp = []
        for s, base in PAIRS[:2]:
            cmp.append(', '.join(change(values(runs, w, base, k), values(runs, w, s, k)) for k, _ in KEYS))
        print(f"| {w} | {' | '.join(cells)} | {' | '.join(cmp)} |")
    print()
    for s, base in PAIRS[2:]:
        for w in worlds:
            print(f"{w}: {s} vs {base}: " + '; '.join(
                f"{name} {change(values(runs, w, base, k), values(runs, w, s, k))}" for k, name in KEYS))
    print()
    by = {(r['world'], r['strategy'], r['seed']): r for rs in runs.values() for r in rs}
    for s, base in PAIRS:
        for k, name in KEYS:
            q = [by[w, s, seed][k] / b[k] for (w, s0, seed), b in by.items() if s0 == base and (w, s, seed) in by]
            if q:
                print(f"all plans: {s} / {base} {name}, paired by plan and seed: median {median(q):.2f}, "
                      f"range {min(q):.2f}..{max(q):.2f}, {sum(v < 1 for v in q)} of {len(q)} shorter, "
                      f"{sum(v > 1 for v in q)} longer")
    print()
    for s, base in PAIRS[:2]:
        short = [w for w in worlds if mean(values(runs, w, s, 'path_length_m'))
                 <= 0.88 * mean(values(runs, w, base, 'path_length_m'))]
        print(f"{s} 12 % or more shorter in path than {base} (mean of the seeds): {len(short)} of {len(worlds)} plans"
              + (f" ({', '.join(short)})" if short else ""))
    either = [w for w in worlds if any(mean(values(runs, w, s, 'path_length_m'))
                                       <= 0.88 * mean(values(runs, w, base, 'path_length_m')) for s, base in PAIRS[:2])]
    print(f"either: {len(either)} of {len(worlds)} plans")
    if old:
        before = load(old)
        print(f"\nEach strategy against {old} (same plans and seeds), time / path:\n")
        print("| world | strategy | before: time, path | now: time, path | time | path |")
        print("|---|---|---|---|---|---|")
        for w in worlds:
            for s in ('nearest', 'utility', 'predictive', 'predictive-utility'):
                a = [values(before, w, s, k) for k, _ in KEYS]
                b = [values(runs, w, s, k) for k, _ in KEYS]
                if not a[0] or not b[0]: continue
                print(f"| {w} | {s} | {mean(a[0]):.0f} s, {mean(a[1]):.0f} m | {mean(b[0]):.0f} s, {mean(b[1]):.0f} m "
                      f"| {change(a[0], b[0])} | {change(a[1], b[1])} |")
        bb = {(r['world'], r['strategy'], r['seed']): r for rs in before.values() for r in rs}
        print()
        for s in ('nearest', 'utility', 'predictive', 'predictive-utility'):
            pairs = [(by[key], bb[key]) for key in by if key[1] == s and key in bb]
            if not pairs: continue
            q = [a['simulated_time_s'] / b['simulated_time_s'] for a, b in pairs]
            same = sum(a['simulated_time_s'] == b['simulated_time_s'] and a['path_length_m'] == b['path_length_m']
                       for a, b in pairs)
            print(f"{s}: now / before time, paired by plan and seed: median {median(q):.2f}, range "
                  f"{min(q):.2f}..{max(q):.2f}, {sum(v < 1 for v in q)} of {len(q)} shorter, {same} unchanged")


if __name__ == '__main__':
    if len(sys.argv) < 2: sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2] if len(sys.argv) > 2 else None)
