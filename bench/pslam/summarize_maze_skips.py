#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Table of bench/pslam/maze_skip_rules.sh: per skip rule the time to the end against the
first folder (nearest), the coverage of explored plus predicted free space (what skipping
left neither explored nor predicted: nearest's full exploration reaches 0.973-0.976), the
predictor's cell accuracy, the look-ahead area explored anyway, and the time per goal by
how much of the goal's far side was predicted when it was chosen (from the debug logs; under
the region rule a frontier counts 0 % or 100 %, so its goals all fall under 0 % or dropped).
Usage: summarize_maze_skips.py OUT BASE RULE...   (SEEDS="1 2 ... 10" reads other seeds than 1-5)"""
import json
import os
import re
import statistics as st
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from summarize_runs import welch  # noqa: E402


def runs(folder, seeds=range(1, 6)):
    out = {}
    for s in seeds:
        path = os.path.join(folder, str(s), "run.json")
        if os.path.exists(path):
            with open(path) as f:
                out[s] = json.load(f)
        log = os.path.join(folder, f"{s}.log")
        if s in out and os.path.exists(log):
            with open(log) as f:
                out[s]["log"] = f.read()
    return out


def time_by_share(log):
    """Seconds from each selection to the next, keyed by the chosen frontier's predicted share."""
    use = {"0 %": 0.0, "1-49 %": 0.0, "50-99 %": 0.0, "dropped": 0.0}
    share, goal, end = None, None, None
    for line in log.splitlines():
        m = re.search(r"chosen frontier of \d+ cells at \([^)]*\) (\d+)% predicted", line)
        if m:
            share = int(m.group(1))
            continue
        m = re.search(r"t ([\d.]+): selection", line)
        if m:
            t = float(m.group(1))
            if goal:
                use[goal[2] or goal[1]] += t - goal[0]
            goal = [t, "0 %" if share == 0 else "1-49 %" if share < 50 else "50-99 %", None] if share is not None else None
            share = None
            continue
        if goal and "dropped: predicted on the way" in line:
            goal[2] = "dropped"
        m = re.search(r"done: ([\d.]+) s simulated", line)
        if m:
            end = float(m.group(1))
    if goal and end:
        use[goal[2] or goal[1]] += end - goal[0]
    return use


def main(out, base, rules):
    seeds = [int(x) for x in os.environ.get("SEEDS", "1 2 3 4 5").split()]
    b = runs(os.path.join(out, base), seeds)
    tb = [b[s]["simulated_time_s"] for s in sorted(b)]
    print(f"{base}: {len(tb)} runs, {st.mean(tb):.1f} +- {st.stdev(tb):.1f} s, explored "
          f"{min(b[s]['coverage'] for s in b):.3f}-{max(b[s]['coverage'] for s in b):.3f}\n")
    print("| rule | time [s] | vs " + base + " | explored | explored + predicted: mean, worst seed | cells right: mean, worst | predicted inside, explored anyway | goal time at 0 / 1-49 / 50-99 % predicted, dropped |")
    print("|---|---|---|---|---|---|---|---|")
    for rule in rules:
        r = runs(os.path.join(out, rule), seeds)
        seeds = sorted(r)
        if not seeds:
            continue
        t = [r[s]["simulated_time_s"] for s in seeds]
        tt, p = welch([b[s]["simulated_time_s"] for s in seeds], t)
        wp = [r[s]["prediction"]["coverage_with_predictions"] for s in seeds]
        acc = [r[s]["prediction"]["cell_accuracy"] for s in seeds]
        ever, left, use = 0.0, 0.0, {}
        for s in seeds:
            m = re.search(r"([\d.]+) m\^2 ever predicted, ([\d.]+) m\^2 still", r[s].get("log", ""))
            if m:
                ever += float(m.group(1))
                left += float(m.group(2))
            for k, v in time_by_share(r[s].get("log", "")).items():
                use[k] = use.get(k, 0.0) + v
        total = sum(use.values()) or 1.0
        shares = " / ".join(f"{100 * use[k] / total:.0f}" for k in ("0 %", "1-49 %", "50-99 %", "dropped"))
        anyway = f"{ever / len(seeds):.0f} m^2, {100 * (ever - left) / ever:.0f} %" if ever else "-"
        print(f"| {rule} | {st.mean(t):.0f} +- {st.stdev(t):.0f} | {100 * (st.mean(t) / st.mean(tb) - 1):+.1f} % (p = {p:.3f}) "
              f"| {st.mean(r[s]['coverage'] for s in seeds):.3f} | {st.mean(wp):.3f}, {min(wp):.3f} | {st.mean(acc):.3f}, {min(acc):.3f} "
              f"| {anyway} | {shares} % |")


if __name__ == "__main__":
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2], sys.argv[3:])
