// SPDX-License-Identifier: MIT
// One planar laser scan with the odometry pose the robot reported for it.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "lookahead/slam/geometry/pose2.hpp"

namespace lookahead::slam {

/// A range scan of a planar laser, in the conventions of DESIGN.md (SI units, radians,
/// beams counter-clockwise from angle_min). Readings that are not finite, not positive, or
/// at/above max_range are no-returns (see is_return()).
struct LaserScan {
  double timestamp = 0.0;  ///< source's own timestamp [s] (CARMEN: ipc timestamp)
  /// CARMEN's logger timestamp (the clock GMapping's .gfs.log outputs print); equal to
  /// `timestamp` for sources with one clock.
  double logger_timestamp = 0.0;
  std::vector<float> ranges;     ///< one reading per beam [m]
  double angle_min = 0.0;        ///< bearing of the first beam in the laser frame [rad]
  double angle_increment = 0.0;  ///< bearing step between beams [rad]
  double max_range = 80.0;       ///< readings >= this are no-returns [m]
  Pose2 laser_offset;            ///< laser pose in the robot frame
  Pose2 odometry;                ///< robot odometry pose at the scan time
  std::size_t source_line = 0;   ///< line (or record) of the log the scan came from

  [[nodiscard]] bool is_return(std::size_t beam) const;
  [[nodiscard]] double bearing(std::size_t beam) const {
    return angle_min + angle_increment * static_cast<double>(beam);
  }
};

}  // namespace lookahead::slam
