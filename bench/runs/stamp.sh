# SPDX-License-Identifier: MIT
# Sourced by every driver in bench/runs: `stamp OUT` writes OUT/machine.txt with what a figure
# in docs/results.md must carry (commit, date, CPU, cores) and prints it.
stamp() {
  mkdir -p "$1"
  {
    echo "commit $(git describe --always --dirty 2>/dev/null || echo unknown)"
    echo "date $(date -u +%F)"
    echo "cpu $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)"
    echo "cores $(nproc)"
  } | tee "$1/machine.txt"
}
