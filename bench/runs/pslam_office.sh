#!/bin/bash
# SPDX-License-Identifier: MIT
# P-SLAM reproduction 2: hypotheses made while exploring office floors, each scored against
# the true world (config/study/pslam_office.yaml). Paper: 56 hypotheses, 36 above 0.4,
# mean 0.51. Run from the repository root after building: bash bench/runs/pslam_office.sh
# LOOKAHEAD=/path/to/lookahead picks another binary (a copy, while you keep building).
set -euo pipefail
cd "$(dirname "$0")/../.."
source bench/runs/stamp.sh
bin=${LOOKAHEAD:-./build/lookahead}
out=out/study/pslam_office
"$bin" study config/study/pslam_office.yaml --out "$out"
stamp "$out"
python3 bench/runs/pslam_summary.py "$out" | tee "$out/pslam_summary.md"
