#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Runs MRPT's rbpf-slam (Debian mrpt-apps 2.5.8) on a CARMEN log and writes its trajectory in
# our format, for the side-by-side comparison in shared/BASELINES.md.
#
#   run_mrpt_rbpf.sh LOG.carmen OUTDIR [PARTICLES=30] [VARIANT=optimal|icp]
#   env: SEED (default 1), EVERY (keep every K-th scan, default 1),
#        CARMEN_TO_RAWLOG (path to the converter; built from this folder if unset)
#
# Writes OUTDIR/trajectory.txt ("ipc_timestamp x y theta", one line per scan fed to MRPT),
# OUTDIR/mrpt_run.json, and keeps MRPT's own files in OUTDIR/mrpt/ and its console in
# OUTDIR/rbpf-slam.log.
#
# The trajectory is the final most likely particle's path (rbpf-slam's most_likely_path.txt).
# That path has one pose per filter update (plus the start pose), and the filter runs only
# after enough odometry motion, so each scan's pose is the pose of the last update at or
# before it composed with the odometry since then (as MRPT's own current-pose estimate does).
# The console tells which steps ran the filter: an INFO "New pose=" line before the step's
# "------------- STEP" line.
set -euo pipefail

die() { echo "run_mrpt_rbpf.sh: $*" >&2; exit 1; }
[[ $# -ge 2 && $# -le 4 ]] || die "usage: run_mrpt_rbpf.sh LOG.carmen OUTDIR [PARTICLES] [VARIANT]"
LOG=$1 OUT=$2 PARTICLES=${3:-30} VARIANT=${4:-optimal}
SEED=${SEED:-1} EVERY=${EVERY:-1}
HERE=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
[[ -f $LOG ]] || die "$LOG: no such file"
[[ $PARTICLES =~ ^[1-9][0-9]*$ ]] || die "PARTICLES must be a positive integer, got '$PARTICLES'"
case $VARIANT in
  optimal) INI=$HERE/rbpf_slam_gridmap.ini ;;
  icp) INI=$HERE/rbpf_slam_icp.ini ;;
  *) die "VARIANT must be optimal or icp, got '$VARIANT'" ;;
esac
command -v rbpf-slam >/dev/null || die "rbpf-slam not found: apt-get install mrpt-apps"
if [[ ! -x /usr/bin/time ]]; then  # GNU time gives peak RSS; bash's builtin does not
  [[ $(id -u) == 0 ]] || die "/usr/bin/time missing: apt-get install time"
  apt-get update -qq && apt-get install -y -qq time >/dev/null
fi

# The converter: given, or built standalone (incremental after the first time).
BIN=${CARMEN_TO_RAWLOG:-}
if [[ -z $BIN ]]; then
  # One build folder per source folder: CMake refuses to reuse one for another checkout.
  BUILD=${TMPDIR:-/tmp}/lookahead-bench-mrpt-$(printf %s "$HERE" | cksum | cut -d' ' -f1)
  cmake -S "$HERE" -B "$BUILD" -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build "$BUILD" --target carmen_to_rawlog >/dev/null
  BIN=$BUILD/carmen_to_rawlog
fi

mkdir -p "$OUT"
OUT=$(cd "$OUT" && pwd)
MRPT_OUT=$OUT/mrpt  # rbpf-slam empties this folder first: never point it at OUTDIR itself
"$BIN" "$LOG" "$OUT/input.rawlog" --every "$EVERY" --scans "$OUT/scans.txt"
sed -e "s#@OUT_DIR@#$MRPT_OUT#" -e "s#@PARTICLES@#$PARTICLES#" -e "s#@SEED@#$SEED#" \
  "$INI" >"$OUT/rbpf_slam.ini"

echo "rbpf-slam: $VARIANT, $PARTICLES particles, seed $SEED ..."
# stdin from /dev/null: on an error rbpf-slam waits for a key press.
/usr/bin/time -v -o "$OUT/time.txt" rbpf-slam "$OUT/rbpf_slam.ini" "$OUT/input.rawlog" \
  </dev/null >"$OUT/rbpf-slam.log" 2>&1 || die "rbpf-slam failed, see $OUT/rbpf-slam.log"

# Per-scan poses: join scans.txt (index ipc odom_x odom_y odom_theta), the filter steps from
# the console and the most likely path.
awk -v console="$OUT/rbpf-slam.log" -v path="$MRPT_OUT/most_likely_path.txt" '
  function wrap(a) { while (a > 3.14159265358979) a -= 6.28318530717959;
                     while (a <= -3.14159265358979) a += 6.28318530717959; return a }
  BEGIN {
    step = 0; n = 0
    while ((getline line < console) > 0) {
      if (line ~ /New pose=/) update[n++] = step
      else if (line ~ /------------- STEP [0-9]+/) step++
    }
    m = 0
    while ((getline line < path) > 0) {
      split(line, f, " "); px[m] = f[1]; py[m] = f[2]; pt[m++] = f[3]
    }
    # path[0] is the start pose; path[j + 1] is the pose after the j-th filter update.
    if (m != n + 1 || n == 0 || update[0] != 0) {
      printf "cannot match: %d filter updates in the console, %d path poses\n", n, m > "/dev/stderr"
      bad = 1; exit 1
    }
    j = -1
  }
  {
    k = NR - 1
    while (j + 1 < n && update[j + 1] <= k) j++
    if (update[j] == k) { ox = $3; oy = $4; ot = $5 }  # odometry at the last update
    # Odometry since that update, in its frame, composed onto the path pose.
    c = cos(ot); s = sin(ot); dx = $3 - ox; dy = $4 - oy
    lx = c * dx + s * dy; ly = -s * dx + c * dy; lt = wrap($5 - ot)
    C = cos(pt[j + 1]); S = sin(pt[j + 1])
    printf "%.6f %.6f %.6f %.6f\n", $2, px[j + 1] + C * lx - S * ly, py[j + 1] + S * lx + C * ly,
           wrap(pt[j + 1] + lt)
  }
  END { if (bad) exit 1
        if (NR != step) { printf "%d scans but %d steps\n", NR, step > "/dev/stderr"; exit 1 } }
' "$OUT/scans.txt" >"$OUT/trajectory.txt" || die "could not build trajectory.txt"

# Wall time is "h:mm:ss" or "m:ss.ss"; peak RSS is in KiB (reported here in MiB).
WALL=$(awk -F': ' '/Elapsed \(wall clock\)/ { n = split($2, t, ":"); s = 0
  for (i = 1; i <= n; i++) s = s * 60 + t[i]; printf "%.2f", s }' "$OUT/time.txt")
PEAK=$(awk -F': ' '/Maximum resident set size/ { printf "%.1f", $2 / 1024 }' "$OUT/time.txt")
SCANS=$(wc -l <"$OUT/trajectory.txt")
FMT='{"wall_s": %s, "peak_mb": %s, "particles": %s, "variant": "%s", "scans": %s, '
FMT+='"seed": %s, "every": %s, "log": "%s"}\n'
# shellcheck disable=SC2059  # the format is ours
printf "$FMT" "$WALL" "$PEAK" "$PARTICLES" "$VARIANT" "$SCANS" "$SEED" "$EVERY" "$LOG" \
  >"$OUT/mrpt_run.json"
cat "$OUT/mrpt_run.json"
