#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# HybridSLAM sec. 5 in full: Table 1 over 100 trials per filter and clutter level (50
# worlds, 500 particles), Fig. 3/4, NEES and the speed run. About 25 min on 2 cores.
# Usage: bench/runs/hybrid_table1.sh [BUILD] [OUT] [TRIALS]
set -euo pipefail
BUILD=${1:-build}
OUT=${2:-out/hybrid-sim}
TRIALS=${3:-100}
mkdir -p "$OUT"
{
  echo "commit $(git rev-parse --short HEAD) $(date -u +%FT%TZ)"
  grep -m1 "model name" /proc/cpuinfo || true
  echo "cores $(nproc)"
} > "$OUT/machine.txt"
"$BUILD/lookahead" hybrid-sim --trials "$TRIALS" --out "$OUT"
cat "$OUT/table1.txt"
