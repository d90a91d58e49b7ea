#!/bin/bash
# SPDX-License-Identifier: MIT
# P-SLAM reproduction 1: the symmetric maze, nearest-frontier exploration against look-ahead
# mapping (config/study/pslam_maze.yaml), then the table of bench/pslam/summarize_runs.py.
# Run from the repository root after building: bash bench/pslam/maze_study.sh
set -euo pipefail
cd "$(dirname "$0")/../.."
./build/lookahead study config/study/pslam_maze.yaml
python3 bench/pslam/summarize_runs.py out/study/pslam_maze | tee out/study/pslam_maze/pslam_summary.md
