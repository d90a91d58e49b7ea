#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Exploration on KTH floor plans (the P2 Explore setup): every strategy of the study file on its
# plans and seeds, with the study's own summary (per world and strategy, paired comparisons).
# Usage: bash bench/runs/kth_study.sh [STUDY.yaml=config/study/kth_p2_setup.yaml]
# (LOOKAHEAD=/path/to/lookahead picks another binary; JOBS=N runs N missions at once, default
# every core.) Report: out/study/<name>/summary.md.
set -euo pipefail
cd "$(dirname "$0")/../.."
source bench/runs/stamp.sh
study=${1:-config/study/kth_p2_setup.yaml}
out=out/study/$(basename "$study" .yaml)
stamp "$out"
"${LOOKAHEAD:-./build/lookahead}" study "$study" --out "$out" ${JOBS:+--jobs "$JOBS"}
cat "$out/summary.md"
