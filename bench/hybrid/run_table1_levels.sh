#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# HybridSLAM Table 1 one clutter level per process (FASTSLAM, EKF, HYBRID; no figures), so a
# finished column survives if a later one is stopped. Each level is level 0 of its own
# study: same 50 worlds as run_table1.sh, other noise and filter seeds.
# Usage: bench/hybrid/run_table1_levels.sh [BUILD] [OUT] [TRIALS]
set -euo pipefail
BUILD=${1:-build}
OUT=${2:-out/hybrid-levels}
TRIALS=${3:-100}
mkdir -p "$OUT"
echo "commit $(git rev-parse --short HEAD) $(date -u +%FT%TZ) cores $(nproc)" > "$OUT/machine.txt"
i=0
for level in "1.0 0.0" "0.7 0.02" "0.4 0.04" "0.1 0.06"; do
  set -- $level
  printf "study:\n  alphas: [%s]\n  betas: [%s]\n  trials: %s\n" "$1" "$2" "$TRIALS" > "$OUT/level$i.yaml"
  start=$(date +%s)
  nice -n 10 "$BUILD/lookahead" hybrid-sim --config "$OUT/level$i.yaml" --no-figures --no-adaptive --out "$OUT/level$i"
  echo "level $i wall $(( $(date +%s) - start )) s" >> "$OUT/machine.txt"
  tail -n 4 "$OUT/level$i/table1.txt"
  i=$((i + 1))
done
