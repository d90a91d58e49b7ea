#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Two SegSLAM binaries (A: a reference, B: a change) on the garage loop, each next to the same
# 3D RBPF run: per filter seed and particle count the RBPF, then A's SegSLAM, then B's, one
# after the other, so both pairs saw the same machine load. Writes OUT/a and OUT/b in
# garage_loop.sh's layout (the RBPF folder is A's, linked into B), for pair_table.py on each:
# compare the medians of per-pair ratios, never one timing.
#
# usage: A=path/to/lookahead B=path/to/lookahead bench/seg3d/ab_loop.sh OUT FIRST_SEED LAST_SEED COUNTS...
#   e.g. A=/tmp/main_bin B=build/lookahead nice -n 10 bench/seg3d/ab_loop.sh out/ab 1 8 1 5
#   A_ARGS / B_ARGS pass options to that binary's SegSLAM runs (e.g. B_ARGS="--wide-reentry-radius 0").
set -euo pipefail
out=$1 first=$2 last=$3
shift 3
a=${A:?A=reference binary}
b=${B:?B=changed binary}
mkdir -p "$out/a" "$out/b"
for seed in $(seq "$first" "$last"); do
  for n in "$@"; do
    args=(slam3d garage --particles "$n" --seed "$seed" --data-seed 1 --map-samples 1)
    rbpf="$out/a/p$n-s$seed"
    if [ ! -f "$rbpf/run.json" ]; then
      echo "rbpf, particles $n, seed $seed"
      "$a" "${args[@]}" --method rbpf --out "$rbpf" > "$rbpf.log" 2>&1
    fi
    ln -sfn "$(cd "$rbpf" && pwd)" "$out/b/p$n-s$seed"
    for side in a b; do
      dir="$out/$side/segslam-p$n-s$seed"
      [ -f "$dir/run.json" ] && continue  # resumable
      echo "segslam $side, particles $n, seed $seed"
      if [ $side = a ]; then bin=$a extra=${A_ARGS:-}; else bin=$b extra=${B_ARGS:-}; fi
      read -r -a extra_args <<< "$extra"
      "$bin" "${args[@]}" --method segslam "${extra_args[@]}" --out "$dir" > "$dir.log" 2>&1
    done
  done
done
