#!/bin/bash
# SPDX-License-Identifier: MIT
# P-SLAM reproduction 2: hypotheses made while exploring office floors, each scored against
# the true world (config/study/pslam_office.yaml). Paper: 56 hypotheses, 36 above 0.4,
# mean 0.51. Run from the repository root after building: bash bench/pslam/office_study.sh
# LOOKAHEAD=/path/to/lookahead picks another binary (a copy, while you keep building).
set -euo pipefail
cd "$(dirname "$0")/../.."
bin=${LOOKAHEAD:-./build/lookahead}
out=out/study/pslam_office
"$bin" study config/study/pslam_office.yaml --out "$out"
python3 bench/pslam/summarize_runs.py "$out" | tee "$out/pslam_summary.md"
