#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""bench/runs/prediction_study.py subset: LASER replaces the study's laser and POSE its pose
source, garbage in either stops the driver with a message naming the value before any
mission runs, and world files are re-rooted to the new study's folder while generated worlds
keep their names."""
import os
import subprocess
import sys
import tempfile
import unittest

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), '..', '..'))
SCRIPT = os.path.join(ROOT, 'bench', 'runs', 'prediction_study.py')
STUDY = os.path.join(ROOT, 'config', 'study', 'kth_all.yaml')


def subset(laser, out):
    return subprocess.run([sys.executable, SCRIPT, 'subset', STUDY, out, 'nearest', '1', '', '800', laser],
                          capture_output=True, text=True)


class LaserSetting(unittest.TestCase):
    def test_the_pioneers_laser_replaces_fov_and_range(self):
        with tempfile.TemporaryDirectory() as d:
            out = os.path.join(d, 'study.yaml')
            r = subset('180 8', out)
            self.assertEqual(r.returncode, 0, r.stderr)
            text = open(out).read()
            self.assertIn('    fov: 3.141592654\n', text)
            self.assertIn('    max_range: 8\n', text)
            self.assertNotIn('max_range: 12', text)
            self.assertIn('strategies: [nearest]', text)

    def test_garbage_is_rejected_naming_the_value(self):
        for bad in ('abc 8', '180', '180 8 2', '0 8', '400 8', '180 -1', '180 nan'):
            with tempfile.TemporaryDirectory() as d:
                out = os.path.join(d, 'study.yaml')
                r = subset(bad, out)
                self.assertNotEqual(r.returncode, 0, bad)
                self.assertIn(f'LASER "{bad}"', r.stderr, bad)
                self.assertFalse(os.path.exists(out), bad)


class PoseSetting(unittest.TestCase):
    def run_subset(self, pose, out):
        return subprocess.run([sys.executable, SCRIPT, 'subset', STUDY, out, 'nearest', '1', '', '800', '', pose],
                              capture_output=True, text=True)

    def test_slam_replaces_the_pose_source(self):
        with tempfile.TemporaryDirectory() as d:
            out = os.path.join(d, 'study.yaml')
            r = self.run_subset('slam', out)
            self.assertEqual(r.returncode, 0, r.stderr)
            text = open(out).read()
            self.assertIn('\npose_source: slam\n', text)
            self.assertNotIn('pose_source: truth', text)
            self.assertIn('max_range: 12', text)  # the laser is left as it was

    def test_garbage_is_rejected_naming_the_value(self):
        for bad in ('SLAM', 'odometry', 'slam truth'):
            with tempfile.TemporaryDirectory() as d:
                out = os.path.join(d, 'study.yaml')
                r = self.run_subset(bad, out)
                self.assertNotEqual(r.returncode, 0, bad)
                self.assertIn(f'POSE "{bad}"', r.stderr, bad)
                self.assertFalse(os.path.exists(out), bad)


class WorldPaths(unittest.TestCase):
    def test_files_are_re_rooted_and_generated_worlds_kept(self):
        study = os.path.join(ROOT, 'config', 'study', 'buildings.yaml')
        with tempfile.TemporaryDirectory() as d:
            out = os.path.join(d, 'sub', 'study.yaml')
            os.makedirs(os.path.dirname(out))
            r = subprocess.run([sys.executable, SCRIPT, 'subset', study, out, 'nearest', '1',
                                'office_2 intel_lab'], capture_output=True, text=True)
            self.assertEqual(r.returncode, 0, r.stderr)
            names = [l.split('name: ')[1].split()[0] for l in open(out) if l.startswith('  - name: ')]
            self.assertEqual(len(names), 2, names)
            self.assertIn('office', names)
            world = [n for n in names if n != 'office'][0]
            self.assertTrue(os.path.isfile(os.path.join(os.path.dirname(out), world)), world)


if __name__ == '__main__':
    unittest.main()
