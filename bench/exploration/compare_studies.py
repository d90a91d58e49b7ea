#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""One study before and after a change, per strategy.

Pairs the runs of two results.csv files by world, strategy and seed, and prints per strategy:
how many runs reach 95 % in each, the geometric mean of the paired time-to-95 % ratios
(after / before) with how many are faster, slower and equal, the runs that changed status,
and per world where a Welch test is possible (two seeds or more) its p-value.

  bench/exploration/compare_studies.py BEFORE_results.csv AFTER_results.csv [BEFORE2.csv ...]

Several BEFORE files are merged (a study whose strategies were run separately).
"""
import math
import sys

from compare_gain import load, welch_p


def key(r):
    return (r['world'], r['strategy'], r['seed'])


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    after = {key(r): r for r in load(sys.argv[2])}
    before = {}
    for path in [sys.argv[1]] + sys.argv[3:]:
        before.update({key(r): r for r in load(path)})
    for strategy in dict.fromkeys(k[1] for k in after):
        pairs = [(before[k], after[k]) for k in after if k[1] == strategy and k in before]
        reached = lambda rows: sum(1 for r in rows if r['time_to_95_s'])
        print(f"## {strategy}: {len(pairs)} paired runs; reach 95 %: before {reached(p[0] for p in pairs)}, "
              f"after {reached(p[1] for p in pairs)}")
        ratios = [float(a['time_to_95_s']) / float(b['time_to_95_s']) for b, a in pairs
                  if a['time_to_95_s'] and b['time_to_95_s']]
        if ratios:
            g = math.exp(sum(math.log(x) for x in ratios) / len(ratios))
            print(f"time to 95 %, after / before: geometric mean {g:.3f} over {len(ratios)} runs "
                  f"({sum(x < 0.999 for x in ratios)} faster, {sum(x > 1.001 for x in ratios)} slower, "
                  f"{sum(abs(x - 1) <= 0.001 for x in ratios)} equal)")
        for b, a in pairs:
            if b['status'] != a['status'] or abs(float(a['coverage']) - float(b['coverage'])) > 0.02:
                print(f"- {'/'.join(key(a))}: {b['status']} {float(b['coverage']):.3f} ({b['time_to_95_s'] or '-'} s) -> "
                      f"{a['status']} {float(a['coverage']):.3f} ({a['time_to_95_s'] or '-'} s)")
        for world in dict.fromkeys(a['world'] for _, a in pairs):
            tb = [float(b['time_to_95_s']) for b, a in pairs if a['world'] == world and b['time_to_95_s']]
            ta = [float(a['time_to_95_s']) for b, a in pairs if a['world'] == world and a['time_to_95_s']]
            p = welch_p(ta, tb)
            if p is not None:
                print(f"  {world}: {sum(tb) / len(tb):.0f} -> {sum(ta) / len(ta):.0f} s, p = {p:.2f}")
        print()


if __name__ == '__main__':
    main()
