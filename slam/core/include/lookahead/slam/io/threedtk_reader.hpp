// SPDX-License-Identifier: MIT
// 3DTK ("uos") scans: scanNNN.3d (one "x y z" point per line, centimetres) with
// scanNNN.pose (line 1: position x y z in cm; line 2: rotation theta_x theta_y theta_z in
// degrees). 3DTK's frame is left-handed: x right, y up, z forward. Points and poses are
// converted to lookahead's right-handed frame (x forward, y left, z up) in metres.
//
// The rotation is R = Ry(theta_y) Rx(theta_x) Rz(theta_z) in 3DTK's axes, reflected into
// ours. For the three scans in shared/data/3d/3dtk_dat every angle is below 1.4 deg, so a
// different composition order would move a point at 30 m by under 1 cm.
#pragma once

#include <string>

#include "lookahead/slam/sensor/range_sweep.hpp"

namespace lookahead::slam {

struct ThreeDtkOptions {
  /// Points at or beyond this range are no-returns (3DTK writes them at 32.76 m) [m].
  double no_return_range = 32.70;
  int point_step = 1;  ///< keep every n-th point, >= 1
};

/// Reads one scan: ParseError names the file, line, field and value of any bad line.
RangeSweep read_3dtk_scan(const std::string& scan_path, const std::string& pose_path,
                          const ThreeDtkOptions& options = {});

/// Reads scan000.3d/.pose, scan001 ... from a folder until the first missing number.
/// The poses are the sweeps' odometry; there is no ground truth.
RangeLog3 read_3dtk_folder(const std::string& folder, const ThreeDtkOptions& options = {});

}  // namespace lookahead::slam
