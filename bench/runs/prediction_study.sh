#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Exploration with and without prediction on every developer KTH plan: runs the study
# (config/study/kth_all.yaml by default) through `lookahead study`, then writes
# out/study/<name>/prediction_study.md with the per-plan table, the paired geometric-mean
# ratios of time to 95 % explored against nearest (95 % bootstrap intervals), the worst plan,
# the missions that did not reach the goal and why, the predictor's funnel and wall time per
# mission (bench/runs/prediction_study.py).
# Usage: bash bench/runs/prediction_study.sh [STUDY.yaml]
#   STRATEGIES="nearest advantage" SEEDS="1 2" PLANS="kth_50055649 kth_50045369" pick a subset,
#   MAX_AREA=800 only the plans of at most 800 m^2 free, LASER="180 8" the Pioneer's laser
#   (field of view in degrees, range in metres) in place of the study's, POSE=slam the RBPF
#   in the loop (POSE=truth: mapping at the true pose) (written as OUT/study.yaml); JOBS=2
#   runs in parallel; LOOKAHEAD=/path/to/lookahead.
set -euo pipefail
cd "$(dirname "$0")/../.."
source bench/runs/stamp.sh
study=${1:-config/study/kth_all.yaml}
out=out/study/$(basename "$study" .yaml)
mkdir -p "$out"
if [[ -n "${STRATEGIES:-}${SEEDS:-}${PLANS:-}${MAX_AREA:-}${LASER:-}${POSE:-}" ]]; then
  python3 bench/runs/prediction_study.py subset "$study" "$out/study.yaml" \
    "${STRATEGIES:-}" "${SEEDS:-}" "${PLANS:-}" "${MAX_AREA:-}" "${LASER:-}" "${POSE:-}"
  study=$out/study.yaml
fi
stamp "$out"
"${LOOKAHEAD:-./build/lookahead}" study "$study" --out "$out" ${JOBS:+--jobs "$JOBS"}
python3 bench/runs/prediction_study.py report "$out" | tee "$out/prediction_study.md"
