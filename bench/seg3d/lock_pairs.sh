#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# SegSLAM 3D with locking and merging off and on next to the 3D RBPF on the garage loop: per
# seed and particle count, the RBPF, SegSLAM (off) and SegSLAM with
# config/segslam/locking.yaml run one after the other (garage_loop.sh, same load for the
# three), into OUT/off (RBPF + SegSLAM) and OUT/on (SegSLAM with locking; the RBPF runs are
# linked in so pair_table.py pairs each seed's on-run with the RBPF run just before it).
#
# usage: bench/seg3d/lock_pairs.sh OUT FIRST_SEED LAST_SEED COUNTS...
#   e.g. LOOKAHEAD=/tmp/bin bench/seg3d/lock_pairs.sh out/lock3d 1 8 5 20
#   then bench/seg3d/pair_table.py OUT/off and OUT/on; bench/seg3d/lock_table.py OUT
set -euo pipefail
out=$1 first=$2 last=$3
shift 3
here=$(dirname "$0")
mkdir -p "$out/off" "$out/on"
for seed in $(seq "$first" "$last"); do
  for n in "$@"; do
    METHODS="rbpf segslam" "$here/garage_loop.sh" "$out/off" "$seed" "$n" > /dev/null
    METHODS="segslam" SEGSLAM_ARGS="--segslam-config config/segslam/locking.yaml" \
      "$here/garage_loop.sh" "$out/on" "$seed" "$n" > /dev/null
    for s in $(seq 1 "$seed"); do
      [ -e "$out/on/p$n-s$s" ] || ln -s "$(realpath "$out/off/p$n-s$s")" "$out/on/p$n-s$s"
    done
    echo "seed $seed, $n particles done"
  done
done
