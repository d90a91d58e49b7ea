#!/bin/bash
# SPDX-License-Identifier: MIT
# P-SLAM reproduction 2: hypotheses made while exploring office floors, each scored against
# the true world (config/study/pslam_office.yaml). Paper: 56 hypotheses, 36 above 0.4,
# mean 0.51. Run from the repository root after building: bash bench/pslam/office_study.sh
set -euo pipefail
cd "$(dirname "$0")/../.."
./build/lookahead study config/study/pslam_office.yaml
python3 bench/pslam/summarize_runs.py out/study/pslam_office | tee out/study/pslam_office/pslam_summary.md
