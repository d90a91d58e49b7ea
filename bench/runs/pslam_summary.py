#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Summarise the P-SLAM figures of a `lookahead study` output folder (each run's run.json):
per world and strategy, mission time and path (mean +- std over seeds), explored coverage,
coverage counting correctly predicted free space, the accuracy of the predicted cells left
at the end, and every hypothesis' Psi against the true world. Welch's t-test on the time
between the first strategy and each other one. Standard library only."""
import json, math, os, sys
from collections import defaultdict

def mean_std(v):
    if not v: return float('nan'), float('nan')
    m = sum(v) / len(v)
    s = math.sqrt(sum((x - m) ** 2 for x in v) / (len(v) - 1)) if len(v) > 1 else 0.0
    return m, s

def welch(a, b):
    """Two-sided Welch t-test; p from the t distribution by numerical integration."""
    if len(a) < 2 or len(b) < 2: return float('nan'), float('nan')
    ma, sa = mean_std(a); mb, sb = mean_std(b)
    va, vb = sa * sa / len(a), sb * sb / len(b)
    if va + vb == 0: return float('nan'), float('nan')
    t = (ma - mb) / math.sqrt(va + vb)
    df = (va + vb) ** 2 / (va * va / (len(a) - 1) + vb * vb / (len(b) - 1))
    # p = I_{df/(df+t^2)}(df/2, 1/2): integrate the t density instead (Simpson, wide range).
    dens = lambda x: math.exp(math.lgamma((df + 1) / 2) - math.lgamma(df / 2)) / math.sqrt(df * math.pi) * (1 + x * x / df) ** (-(df + 1) / 2)
    n, hi = 4000, abs(t); h = hi / n
    inner = dens(0) + dens(hi) + sum((4 if i % 2 else 2) * dens(i * h) for i in range(1, n))
    return t, max(0.0, 1 - 2 * inner * h / 3)

def skip_protocol(r):
    """A run under P-SLAM's protocol (sec. V-A.1): a predictive mission's time and path end
    where every frontier left was predicted or explored-or-correctly-predicted reached the
    goal (the mission itself goes on until the area is explored)."""
    p = r.get('prediction', {})
    if p.get('skip_protocol_end_s') is not None and r['strategy'].startswith('predictive'):
        r = dict(r, simulated_time_s=p['skip_protocol_end_s'], path_length_m=p['path_at_skip_end_m'],
                 coverage_with_predictions=p['coverage_with_predictions_at_skip_end'])
    return r

def load(folder):
    runs = defaultdict(list)
    for root, _, files in os.walk(folder):
        if 'run.json' in files and not root.endswith('.partial'):
            j = json.load(open(os.path.join(root, 'run.json')))
            runs[(j['world'], j['strategy'])].append(skip_protocol(j))
    return runs

def pooled(runs):
    """Over several worlds: each strategy's time and path as a ratio to the first strategy's
    in the same world and seed (median and range of the paired ratios)."""
    worlds = sorted({w for w, _ in runs})
    if len(worlds) < 2: return
    strategies = sorted({s for _, s in runs})
    by = {(r['world'], s, r['seed']): r for (w, s), rs in runs.items() for r in rs}
    print()
    for s in strategies[1:]:
        pairs = [(by[w, s, seed], base) for (w, s0, seed), base in by.items()
                 if s0 == strategies[0] and (w, s, seed) in by]
        if not pairs: continue
        for key, name in (('simulated_time_s', 'time'), ('path_length_m', 'path')):
            q = sorted(a[key] / b[key] for a, b in pairs)
            med = q[len(q) // 2] if len(q) % 2 else (q[len(q) // 2 - 1] + q[len(q) // 2]) / 2
            print(f"all worlds: {s} / {strategies[0]} {name}, paired by world and seed: median {med:.2f}, "
                  f"range {q[0]:.2f}..{q[-1]:.2f}, {sum(v < 1 for v in q)} of {len(q)} shorter")

def main(folder):
    runs = load(folder)
    if not runs: sys.exit(f"{folder}: no run.json found")
    print(f"| world | strategy | runs | end | time [s] | path [m] | explored | with predictions | all predicted cells right | final predicted cells right | ... inside the building | hypotheses | Psi vs world: mean, > 0.4 |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    all_psi, all_solid, times, paths = [], [], defaultdict(list), defaultdict(list)
    for (world, strategy), rs in sorted(runs.items()):
        t = [r['simulated_time_s'] for r in rs]; times[world, strategy] = t
        p = [r['path_length_m'] for r in rs]; paths[world, strategy] = p
        cov = [r['coverage'] for r in rs]
        pr = [r.get('prediction', {}) for r in rs]
        covp = [r.get('coverage_with_predictions', x.get('coverage_with_predictions', c)) for r, x, c in zip(rs, pr, cov)]
        acc = [x['final_predicted_accuracy'] for x in pr if x.get('final_predicted_area_m2', 0) > 0]
        acc_in = [x['final_predicted_accuracy_inside'] for x in pr if x.get('final_predicted_area_inside_m2', 0) > 0]
        acc_all = [x['cell_accuracy'] for x in pr if x.get('hypotheses', 0) > 0]
        psi = [v for x in pr for v in x.get('psi_world', [])]; all_psi += psi
        all_solid += [v for x in pr for v in x.get('psi_solid_world', [])]
        ends = ', '.join(sorted({r['status'] for r in rs}))
        f = lambda v, d=0: '%.*f +- %.*f' % (d, mean_std(v)[0], d, mean_std(v)[1]) if v else '-'
        psi_txt = '%.2f, %.0f %%' % (sum(psi) / len(psi), 100 * sum(v > 0.4 for v in psi) / len(psi)) if psi else '-'
        print(f"| {world} | {strategy} | {len(rs)} | {ends} | {f(t)} | {f(p, 1)} | {f(cov, 3)} | {f(covp, 3)} | {f(acc_all, 2)} | {f(acc, 2)} | {f(acc_in, 2)} | {sum(len(x.get('psi_world', [])) for x in pr)} | {psi_txt} |")
    print()
    for world in sorted({w for w, _ in times}):
        strategies = sorted(s for w, s in times if w == world)
        for s in strategies[1:]:
            a, b = times[world, strategies[0]], times[world, s]
            tt, pp = welch(a, b)
            ma, mb = mean_std(a)[0], mean_std(b)[0]
            pa, pb = paths[world, strategies[0]], paths[world, s]
            pt, ppp = welch(pa, pb)
            print(f"{world}: {s} vs {strategies[0]}: time {100 * (mb - ma) / ma:+.1f} %, Welch t = {tt:.2f}, p = {pp:.3f}; "
                  f"path {100 * (mean_std(pb)[0] - mean_std(pa)[0]) / mean_std(pa)[0]:+.1f} %, t = {pt:.2f}, p = {ppp:.3f}")
    pooled(runs)
    if all_psi:
        print(f"\nall hypotheses: {len(all_psi)}, Psi against the world: mean {sum(all_psi) / len(all_psi):.2f}, "
              f"{sum(v > 0.4 for v in all_psi)} above 0.4 ({100 * sum(v > 0.4 for v in all_psi) / len(all_psi):.0f} %), "
              f"range {min(all_psi):.2f}..{max(all_psi):.2f}")
    if all_solid:  # every world cell, solid outside included (space no robot observes)
        print(f"against every world cell instead (solid beyond the outer walls): mean {sum(all_solid) / len(all_solid):.2f}, "
              f"{sum(v > 0.4 for v in all_solid)} above 0.4 ({100 * sum(v > 0.4 for v in all_solid) / len(all_solid):.0f} %)")

if __name__ == '__main__':
    main(sys.argv[1] if len(sys.argv) > 1 else 'out/study/pslam_maze')
