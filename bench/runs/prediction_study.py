#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The report of bench/runs/prediction_study.sh, from a `lookahead study` folder (each run's
run.json). Standard library only.

  prediction_study.py report OUT          markdown on stdout
  prediction_study.py subset STUDY OUT STRATEGIES SEEDS PLANS [MAX_AREA [LASER [POSE]]]
                                          STUDY with only the named strategies, seeds and
                                          plan labels (space-separated; empty: all), only
                                          plans of at most MAX_AREA m^2 free, with LASER
                                          "FOV_DEG RANGE_M" the laser's field of view and
                                          range replaced (the Pioneer's: "180 8"), and with
                                          POSE (slam | truth) the pose source replaced

Paired comparisons: per plan and seed, a strategy's time to 95 % of the reachable area
explored over nearest's; the geometric mean of these ratios with a 95 % bootstrap interval
(plans resampled, 2000 draws, fixed seed). A pair counts only where both reached 95 %.
A mission that ended at the time limit "needs more time" when its plan's reachable area,
swept at the exploration rate of the missions that reached the goal (median m^2 explored
per metre driven), takes longer than the limit at the robot's speed."""
import json, math, os, random, re, sys
from collections import defaultdict

SPEED = 0.2  # m/s, MissionOptions::robot.max_speed (the study files keep it)
# With SLAM in the loop, a mission whose estimate was off by more than this on average (2.5
# radii of the P2 robot) explored with a map that no longer fit the building.
SLAM_LOST_M = 0.5


def load(folder):
    runs = []
    for root, _, files in os.walk(os.path.join(folder, 'runs')):
        if 'run.json' in files and not root.endswith('.partial'):
            runs.append(json.load(open(os.path.join(root, 'run.json'))))
    return runs


def geomean(v):
    return math.exp(sum(math.log(x) for x in v) / len(v))


def bootstrap(pairs_by_plan, draws=2000):
    rng = random.Random(1)
    plans = list(pairs_by_plan)
    means = []
    for _ in range(draws):
        sample = [r for p in (rng.choice(plans) for _ in plans) for r in pairs_by_plan[p]]
        means.append(geomean(sample))
    means.sort()
    return means[int(0.025 * draws)], means[int(0.975 * draws) - 1]


def t95(r):
    return r.get('time_to_95_s')


def report(folder):
    runs = load(folder)
    if not runs:
        sys.exit(f'{folder}: no run.json found')
    by = {(r['world'], r['strategy'], r['seed']): r for r in runs}
    strategies = sorted({r['strategy'] for r in runs}, key=lambda s: (s != 'nearest', s))
    plans = sorted({r['world'] for r in runs})
    print(f'# Time to 95 % explored, {len(plans)} plans, {len(runs)} missions\n')
    print('## Per plan (median over seeds, s; "-" did not reach 95 %)\n')
    print('| plan | area [m^2] | ' + ' | '.join(strategies) + ' |')
    print('|---|---|' + '---|' * len(strategies))
    for p in plans:
        area = next(r['reachable_free_area_m2'] for r in runs if r['world'] == p)
        cells = []
        for s in strategies:
            v = sorted(t95(r) for r in runs if r['world'] == p and r['strategy'] == s and t95(r) is not None)
            n = sum(1 for r in runs if r['world'] == p and r['strategy'] == s)
            cells.append(f'{v[len(v) // 2]:.0f}' + ('' if len(v) == n else f' ({n - len(v)} short)') if v else '-')
        print(f'| {p} | {area:.0f} | ' + ' | '.join(cells) + ' |')
    print('\n## Paired against nearest (time to 95 % explored)\n')
    print('| strategy | pairs | geometric mean ratio | 95 % interval | faster in | worst plan (ratio) | wall time ratio |')
    print('|---|---|---|---|---|---|---|')
    for s in strategies[1:]:
        pairs = defaultdict(list)
        walls = []
        for (w, st, seed), r in by.items():
            base = by.get((w, 'nearest', seed))
            if st != s or base is None:
                continue
            walls.append(r['wall_time_s'] / base['wall_time_s'])
            if t95(r) is not None and t95(base) is not None:
                pairs[w].append(t95(r) / t95(base))
        flat = [x for v in pairs.values() for x in v]
        if not flat:
            continue
        lo, hi = bootstrap(pairs)
        worst = max(pairs, key=lambda w: geomean(pairs[w]))
        print(f'| {s} | {len(flat)} | {geomean(flat):.3f} | {lo:.3f} .. {hi:.3f} | {sum(x < 1 for x in flat)} | '
              f'{worst} ({geomean(pairs[worst]):.2f}) | {geomean(walls):.2f} |')
    short_report(runs)
    skip_report(runs)
    funnel_report(runs)
    print('\n## Wall time per mission [s]\n')
    print('| strategy | missions | mean | median | max |')
    print('|---|---|---|---|---|')
    for s in strategies:
        w = sorted(r['wall_time_s'] for r in runs if r['strategy'] == s)
        print(f'| {s} | {len(w)} | {sum(w) / len(w):.1f} | {w[len(w) // 2]:.1f} | {w[-1]:.1f} |')


def short_report(runs):
    done = [r for r in runs if t95(r) is not None and r['path_to_95_m']]
    rates = sorted(0.95 * r['reachable_free_area_m2'] / r['path_to_95_m'] for r in done)
    rate = rates[len(rates) // 2] if rates else float('nan')
    short = [r for r in runs if t95(r) is None]
    print(f'\n## Missions that did not reach 95 % explored: {len(short)} of {len(runs)}\n')
    if not short:
        return
    print(f'Exploration rate of the missions that did: median {rate:.2f} m^2 per metre driven; at '
          f'{SPEED} m/s a plan needs about 0.95 x area / rate / speed seconds.\n')
    print('| plan | strategy | seed | status | explored | needed at that rate [s] | why |')
    print('|---|---|---|---|---|---|---|')
    for r in sorted(short, key=lambda r: (r['world'], r['strategy'], r['seed'])):
        need = 0.95 * r['reachable_free_area_m2'] / rate / SPEED
        print(f"| {r['world']} | {r['strategy']} | {r['seed']} | {r['status']} | {r['coverage']:.3f} | {need:.0f} | "
              f"{why_short(r, need)} |")


def why_short(r, need):
    """Why a mission ended short of 95 %: its status, the plan's size against the time limit,
    and a SLAM estimate that lost the robot."""
    if r['status'] == 'time_limit':
        why = 'the plan needs more time than the limit' if need > r['simulated_time_s'] else 'time limit on a plan that fits in it'
    else:
        why = {'done': 'no frontier with a goal left', 'trapped': 'no reachable frontier',
               'collision': 'collision'}.get(r['status'], r['status'])
    error = r.get('slam_position_error_mean_m')
    if error is not None and error > SLAM_LOST_M:
        why += f'; SLAM lost the robot (mean position error {error:.1f} m)'
    return why


def skip_report(runs):
    rows = [r for r in runs if r.get('prediction', {}).get('skip_protocol_end_s') is not None]
    if not rows:
        return
    print('\n## P-SLAM skip protocol (explored or correctly predicted; reported apart)\n')
    print('| plan | strategy | seed | skip protocol end [s] | explored or correctly predicted then | time to 95 % explored [s] |')
    print('|---|---|---|---|---|---|')
    for r in sorted(rows, key=lambda r: (r['world'], r['strategy'], r['seed'])):
        p = r['prediction']
        print(f"| {r['world']} | {r['strategy']} | {r['seed']} | {p['skip_protocol_end_s']:.0f} | "
              f"{p['coverage_with_predictions_at_skip_end']:.3f} | {f'{t95(r):.0f}' if t95(r) is not None else '-'} |")


def funnel_report(runs):
    funnel = defaultdict(lambda: [0] * 12)
    for r in runs:
        p = r.get('prediction')
        if not p:
            continue
        f = funnel[r['strategy']]
        f[0] += p['requests']; f[1] += p['no_control_point']; f[2] += p['no_match']; f[3] += p['hypotheses']
        for h in p.get('hypothesis_list', []):
            f[4] += h.get('cells', 0); f[5] += h.get('cells_right', 0)
            f[6] += h.get('wall_cells', 0); f[7] += h.get('wall_cells_right', 0)
        u = p.get('in_use', {})
        f[8] += u.get('cells', 0); f[9] += u.get('cells_right', 0)
        f[10] += u.get('wall_cells', 0); f[11] += u.get('wall_cells_right', 0)
    if not funnel:
        return
    share = lambda right, all: f'{right / all:.3f}' if all else '-'
    print('\n## Predictor funnel (summed over missions)\n')
    print('In use: the predicted cells, still unexplored and inside the building, that the target choices '
          'read (summed over choices); the walls are what a gain seen through the prediction stops at.\n')
    print('| strategy | targets asked | no control point | no match above Psi threshold | hypotheses '
          '| hypothesis cells right | predicted wall cells right | in use: cells right | in use: walls right |')
    print('|---|---|---|---|---|---|---|---|---|')
    for s, f in sorted(funnel.items()):
        print(f'| {s} | {f[0]} | {f[1]} | {f[2]} | {f[3]} | {share(f[5], f[4])} | {share(f[7], f[6])} '
              f'| {share(f[9], f[8])} | {share(f[11], f[10])} |')


def laser_setting(laser):
    """LASER "FOV_DEG RANGE_M" as two numbers, fov in (0, 360], range > 0; exits naming the value."""
    words = laser.split()
    try:
        fov_deg, max_range = (float(v) for v in words)
    except ValueError:
        sys.exit(f'LASER "{laser}": expected two numbers, "FOV_DEG RANGE_M" (the Pioneer\'s: "180 8")')
    if not 0 < fov_deg <= 360 or not max_range > 0:
        sys.exit(f'LASER "{laser}": the field of view must be in (0, 360] degrees and the range > 0 m')
    return fov_deg, max_range


def subset(study, out, strategies, seeds, plans, max_area='', laser='', pose=''):
    if pose and pose not in ('slam', 'truth'):
        sys.exit(f'POSE "{pose}": expected slam (the RBPF in the loop) or truth')
    text = open(study).read()
    base = os.path.relpath(os.path.dirname(os.path.abspath(study)), os.path.dirname(os.path.abspath(out)))
    head, rest = text.split('worlds:\n', 1)
    worlds, tail = rest.split('strategies:', 1)
    items = worlds.split('  - name: ')[1:]
    if plans.split():
        items = [i for i in items if re.search(r'label: (\S+)', i).group(1) in plans.split()]
    if max_area:  # the free area each world's comment states: "# W m x H m, A m^2 free"
        items = [i for i in items if int(re.search(r'(\d+) m\^2 free', i).group(1)) <= float(max_area)]
    generated = ('office', 'maze', 'corridor')  # built by code: a name, not a path
    items = [re.sub(r'^(\S+)', lambda m: m.group(1) if m.group(1) in generated else os.path.join(base, m.group(1)), i)
             for i in items]
    tail = 'strategies:' + tail
    if strategies.split():
        tail = re.sub(r'strategies: \[[^\]]*\]', 'strategies: [' + ', '.join(strategies.split()) + ']', tail)
    if seeds.split():
        tail = re.sub(r'seeds: .*', 'seeds: [' + ', '.join(seeds.split()) + ']', tail)
    if laser.split():
        fov_deg, max_range = laser_setting(laser)
        tail, n_fov = re.subn(r'(\n\s+fov: )\S+.*', lambda m: f'{m.group(1)}{math.radians(fov_deg):.9f}', tail)
        tail, n_range = re.subn(r'(\n\s+max_range: )\S+.*', lambda m: f'{m.group(1)}{max_range:g}', tail)
        if n_fov != 1 or n_range != 1:
            sys.exit(f'{study}: LASER needs exactly one mission.laser fov and max_range to replace')
    if pose:
        tail, n = re.subn(r'\npose_source: \S+', f'\npose_source: {pose}', tail)
        if n != 1:
            sys.exit(f'{study}: POSE needs exactly one top-level pose_source to replace')
    open(out, 'w').write(head + 'worlds:\n' + ''.join('  - name: ' + i for i in items) + tail)


if __name__ == '__main__':
    if len(sys.argv) >= 3 and sys.argv[1] == 'report':
        report(sys.argv[2])
    elif len(sys.argv) in (7, 8, 9, 10) and sys.argv[1] == 'subset':
        subset(*sys.argv[2:])
    else:
        sys.exit(__doc__)
