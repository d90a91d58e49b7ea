#!/bin/bash
# SPDX-License-Identifier: MIT
# P-SLAM reproduction 1: the symmetric maze, exploration without and with look-ahead mapping,
# then the table of bench/runs/pslam_summary.py. Two protocols:
#   config/study/pslam_maze.yaml       both to the 95 % coverage goal (4 strategies)
#   config/study/pslam_maze_full.yaml  the paper's: full coverage against leaving out the
#                                      predicted regions
# Run from the repository root after building: bash bench/runs/pslam_maze.sh [STUDY.yaml]
# (LOOKAHEAD=/path/to/lookahead picks another binary.)
set -euo pipefail
cd "$(dirname "$0")/../.."
source bench/runs/stamp.sh
study=${1:-config/study/pslam_maze.yaml}
out=out/study/$(basename "$study" .yaml)
"${LOOKAHEAD:-./build/lookahead}" study "$study" --out "$out"
stamp "$out"
python3 bench/runs/pslam_summary.py "$out" | tee "$out/pslam_summary.md"
