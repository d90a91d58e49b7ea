#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Missions per hour of `lookahead study` on this machine: the local runner at 1 and 2
# workers, and the one-node Slurm cluster (scripts/slurm_local.sh) at the same parallelism,
# once with one array task per mission (the per-mission Slurm overhead) and once with one
# task per core. Writes out/study_throughput/report.md. Run as root from the repository:
#   scripts/study_throughput.sh [BUILD_DIR] [SEEDS] [TIME_LIMIT]
set -euo pipefail

build=${1:-build}
seeds=${2:-4}
time_limit=${3:-30}
bin=$(realpath "$build/lookahead")
root=$(pwd)/out/study_throughput
rm -rf "$root"
mkdir -p "$root"
export LOOKAHEAD_SLURM_DIR=$root/slurm
trap 'scripts/slurm_local.sh stop >/dev/null 2>&1 || true' EXIT

study() {  # name: 3 generated worlds x 2 strategies x $seeds seeds
  cat > "$root/$1.yaml" <<YAML
name: $1
out: $root/$1
worlds: [{name: maze}, {name: corridor}, {name: office}]
strategies: [nearest, utility]
seeds: {from: 1, count: $seeds}
pose_source: truth
time_limit: $time_limit
YAML
  echo "$root/$1.yaml"
}

missions=$((3 * 2 * seeds))
now() { date +%s.%N; }
report=$root/report.md
{
  echo "# Study throughput"
  echo
  echo "$missions missions (maze, corridor, office x nearest, utility x $seeds seeds, true pose, $time_limit s simulated)"
  echo "CPU: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(nproc) cores; load before: $(cut -d' ' -f1-3 /proc/loadavg)"
  echo "commit: $(git rev-parse --short HEAD), $(date -u +%Y-%m-%d)"
  echo
  echo "| runner | wall [s] | missions/h | mean mission wall [s] |"
  echo "|---|---|---|---|"
} > "$report"

row() {  # label wall out
  local mean
  mean=$(awk -F, 'NR==1{for(i=1;i<=NF;i++) if($i=="wall_time_s") c=i} NR>1{s+=$c; n++} END{printf "%.2f", s/n}' "$3/results.csv")
  awk -v l="$1" -v w="$2" -v m="$missions" -v mean="$mean" \
    'BEGIN{printf "| %s | %.1f | %.0f | %s |\n", l, w, m * 3600 / w, mean}' >> "$report"
}

for jobs in 1 2; do
  f=$(study "local_$jobs")
  t0=$(now); "$bin" study "$f" --jobs "$jobs" > "$root/local_$jobs.log" 2>&1; t1=$(now)
  row "local, $jobs worker(s)" "$(echo "$t1 - $t0" | bc)" "$root/local_$jobs"
done

eval "$(scripts/slurm_local.sh start)"
run_array() {  # name shards
  local f out array merge
  f=$(study "$1")
  cd "$root"
  t0=$(now)
  out=$("$bin" study slurm "$f" --shards "$2" --submit 2>&1 | tail -n1)
  array=$(echo "$out" | sed -n 's/array job \([0-9]*\), merge job \([0-9]*\)/\1/p')
  merge=$(echo "$out" | sed -n 's/array job \([0-9]*\), merge job \([0-9]*\)/\2/p')
  while [ -n "$(squeue -h -j "$merge" -o %i 2>/dev/null)" ]; do sleep 0.2; done
  t1=$(now)
  cd - > /dev/null
  row "Slurm, $2 array task(s), 1 core each" "$(echo "$t1 - $t0" | bc)" "$root/$1"
  test "$(wc -l < "$root/$1/missing.txt")" -eq 0
}
run_array slurm_per_mission "$missions"
run_array slurm_per_core "$(nproc)"
scripts/slurm_local.sh stop
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)" >> "$report"
cat "$report"
