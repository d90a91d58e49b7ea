#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""P-SLAM reproduction 3, a lookahead rule against the defaults: two `lookahead study` folders of
the KTH plans, each with nearest and predictive runs (the same seeds; nearest does not predict,
so a rule's study may hold a copy of the defaults' nearest runs). Per plan: time and path of
nearest and of both predictive, Welch's test of the rule's predictive against nearest and
against the defaults' predictive, hypotheses and predicted cells right; then the paired-by-seed
ratios and every predictive run's cells right.

  python3 bench/pslam/compare_kth_rule.py DEFAULTS_OUT RULE_OUT

Standard library only (summarize_runs.py's loader and t-test, compare_kth.py's helpers)."""
import os, sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from summarize_runs import load, mean_std  # noqa: E402
from compare_kth import values, change, median  # noqa: E402

KEYS = ('simulated_time_s', 'path_length_m')


def cells_right(rs):
    a = [x['prediction']['cell_accuracy'] for x in rs if x.get('prediction', {}).get('hypotheses', 0) > 0]
    return a


def main(defaults, rule):
    d, r = load(defaults), load(rule)
    worlds = sorted({w for w, _ in d})
    f = lambda v: f"{mean_std(v)[0]:.0f} +- {mean_std(v)[1]:.0f}" if v else '-'
    print("| world | runs: nearest, defaults, rule | nearest: time [s], path [m] | predictive, defaults | predictive, rule "
          "| rule vs nearest: time, path (Welch) | rule vs defaults' predictive: time (Welch) | hypotheses: defaults, rule "
          "| predicted cells right: defaults, rule (runs with a hypothesis) |")
    print("|---|---|---|---|---|---|---|---|---|")
    for w in worlds:
        n = [values(d, w, 'nearest', k) for k in KEYS]
        pd = [values(d, w, 'predictive', k) for k in KEYS]
        pr = [values(r, w, 'predictive', k) for k in KEYS]
        hyp = [sum(len(x['prediction'].get('psi_world', [])) for x in runs.get((w, 'predictive'), [])) for runs in (d, r)]
        acc = [cells_right(runs.get((w, 'predictive'), [])) for runs in (d, r)]
        acc = [f"{sum(a) / len(a):.2f} ({len(a)})" if a else '-' for a in acc]
        print(f"| {w} | {len(n[0])}, {len(pd[0])}, {len(pr[0])} | {f(n[0])}, {f(n[1])} | {f(pd[0])}, {f(pd[1])} "
              f"| {f(pr[0])}, {f(pr[1])} | {change(n[0], pr[0])}, {change(n[1], pr[1])} | {change(pd[0], pr[0])} "
              f"| {hyp[0]}, {hyp[1]} | {acc[0]}, {acc[1]} |")
    print()
    for name, runs in (('defaults', d), ('rule', r)):
        by = {(x['world'], x['strategy'], x['seed']): x for rs in runs.values() for x in rs}
        base = d if name == 'rule' else runs  # the rule's nearest may live in the defaults' folder only
        nb = {(x['world'], x['seed']): x for rs in base.values() for x in rs if x['strategy'] == 'nearest'}
        pairs = [(by[k], nb[k[0], k[2]]) for k in by if k[1] == 'predictive' and (k[0], k[2]) in nb]
        q = [a['simulated_time_s'] / b['simulated_time_s'] for a, b in pairs]
        same = sum(a['simulated_time_s'] == b['simulated_time_s'] for a, b in pairs)
        if q:
            print(f"{name}: predictive / nearest time, paired by plan and seed: median {median(q):.3f}, range "
                  f"{min(q):.2f}..{max(q):.2f}, {sum(v < 1 for v in q)} of {len(q)} shorter, {sum(v > 1 for v in q)} "
                  f"longer, {same} the same to the 0.1 s")
        pr = [x for (w, s), rs in runs.items() if s == 'predictive' for x in rs]
        acc = sorted((a, x['world'], x['seed']) for x in pr for a in cells_right([x]))
        psi = [v for x in pr for v in x.get('prediction', {}).get('psi_world', [])]
        print(f"  {len(pr)} predictive runs, ends {', '.join(sorted({x['status'] for x in pr}))}; {len(psi)} hypotheses"
              + (f", Psi against the world {sum(psi) / len(psi):.2f}, {100 * sum(v > 0.4 for v in psi) / len(psi):.0f} % above 0.4"
                 if psi else ''))
        if acc:
            print(f"  cells right over the {len(acc)} runs with a hypothesis: mean {sum(a for a, _, _ in acc) / len(acc):.2f}, "
                  f"{sum(a < 0.9 for a, _, _ in acc)} below 0.9; worst " + ', '.join(f"{w} seed {s} {a:.2f}" for a, w, s in acc[:3]))


if __name__ == '__main__':
    if len(sys.argv) != 3: sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
