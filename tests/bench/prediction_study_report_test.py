#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""bench/runs/prediction_study.py report: every mission short of 95 % explored gets a reason:
the plan's size against the time limit, the status, and a SLAM estimate that lost the robot."""
import json
import os
import subprocess
import sys
import tempfile
import unittest

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), '..', '..'))
SCRIPT = os.path.join(ROOT, 'bench', 'runs', 'prediction_study.py')


def run(world, strategy, seed, t95, status='coverage_reached', coverage=0.95, slam_error=None):
    r = {'world': world, 'strategy': strategy, 'seed': seed, 'time_to_95_s': t95,
         'path_to_95_m': t95 * 0.2 if t95 else None, 'reachable_free_area_m2': 100.0, 'wall_time_s': 10.0,
         'status': status, 'simulated_time_s': t95 or 1800.0, 'coverage': coverage}
    if slam_error is not None:
        r['slam_position_error_mean_m'] = slam_error
    return r


def report(runs):
    with tempfile.TemporaryDirectory() as d:
        for r in runs:
            folder = os.path.join(d, 'runs', f"{r['world']}__{r['strategy']}__{r['seed']}")
            os.makedirs(folder)
            json.dump(r, open(os.path.join(folder, 'run.json'), 'w'))
        out = subprocess.run([sys.executable, SCRIPT, 'report', d], capture_output=True, text=True)
        assert out.returncode == 0, out.stderr
        return out.stdout


class ShortMissions(unittest.TestCase):
    def test_each_short_mission_says_why(self):
        text = report([
            run('a', 'nearest', 1, 500.0), run('a', 'rate', 1, 400.0),
            # 95 m^2 at 1 m^2 per metre and 0.2 m/s needs 475 s: a time limit at 1800 s is not the size
            run('b', 'nearest', 1, None, 'time_limit', 0.90, slam_error=2.8),
            run('b', 'rate', 1, None, 'time_limit', 0.93, slam_error=0.2),
            run('c', 'nearest', 1, None, 'done', 0.80),
        ])
        self.assertIn('Missions that did not reach 95 % explored: 3 of 5', text)
        lines = {l.split(' | ')[0] + l.split(' | ')[1]: l for l in text.splitlines() if l.startswith('| b |') or l.startswith('| c |')}
        self.assertIn('time limit on a plan that fits in it; SLAM lost the robot (mean position error 2.8 m)',
                      lines['| bnearest'])
        self.assertTrue(lines['| brate'].endswith('time limit on a plan that fits in it |'), lines['| brate'])
        self.assertIn('no frontier with a goal left', lines['| cnearest'])


if __name__ == '__main__':
    unittest.main()
