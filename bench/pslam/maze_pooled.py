#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Pooled figures of maze_skip_rules.sh runs over many seeds: each rule's mean time against the
baseline's over the seeds both have, with a bootstrap 95 % interval of the time change (seeds
resampled with replacement on each side, 5000 draws, fixed seed), the predicted cells right
(mean, worst seed, seeds below 90 %), the look-ahead map left at the end right inside the
building, and the longest prediction's wall time (what a latency setting must cover).
Usage: maze_pooled.py OUT BASE RULE...   (SEEDS="1 2 ... 20" picks the seeds; default 1-20)"""
import os
import random
import statistics as st
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from summarize_maze_skips import runs as load  # noqa: E402  (seed folders' run.json)


def bootstrap_change(times, base_times, draws=5000):
    rng = random.Random(1)
    changes = sorted(
        st.mean(rng.choices(times, k=len(times))) / st.mean(rng.choices(base_times, k=len(base_times))) - 1
        for _ in range(draws))
    return changes[int(0.025 * draws)], changes[int(0.975 * draws) - 1]


def main(out, base, rules):
    seeds = [int(x) for x in os.environ.get("SEEDS", " ".join(map(str, range(1, 21)))).split()]
    b = load(os.path.join(out, base), seeds)
    for rule in rules:
        r = load(os.path.join(out, rule), seeds)
        both = sorted(set(r) & set(b))
        if len(both) < 2:
            print(f"{rule}: fewer than 2 seeds with {base}")
            continue
        t = [r[s]["simulated_time_s"] for s in both]
        tb = [b[s]["simulated_time_s"] for s in both]
        lo, hi = bootstrap_change(t, tb)
        p = [r[s]["prediction"] for s in both]
        right = [x["cell_accuracy"] for x in p]
        inside = [x["final_predicted_accuracy_inside"] for x in p]
        ends = {e: [r[s]["status"] for s in both].count(e) for e in sorted({r[s]["status"] for s in both})}
        print(f"{rule}: {len(both)} seeds, {st.mean(t):.1f} +- {st.stdev(t):.1f} s against {base}'s "
              f"{st.mean(tb):.1f} +- {st.stdev(tb):.1f} s: {100 * (st.mean(t) / st.mean(tb) - 1):+.1f} % "
              f"(95 % bootstrap interval {100 * lo:+.1f} .. {100 * hi:+.1f} %); predicted cells right "
              f"{st.mean(right):.3f}, worst seed {min(right):.3f}, {sum(x < 0.9 for x in right)} seeds below 0.9; "
              f"look-ahead map left at the end right inside {st.mean(inside):.3f}, worst {min(inside):.3f}; "
              f"longest prediction {max(x['max_prediction_s'] for x in p):.3f} s wall; ends {ends}")


if __name__ == "__main__":
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2], sys.argv[3:])
