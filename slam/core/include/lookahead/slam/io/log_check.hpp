// SPDX-License-Identifier: MIT
// What a laser log holds before it is mapped, and what in it would mislead the filter:
// irregular scan rates and gaps, time going backwards, the same scan carried in several
// messages, odometry jumps, changes of beam count or field of view, no-return readings,
// scans without odometry, and a reference trajectory that does not cover the log.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "lookahead/slam/geometry/pose2.hpp"
#include "lookahead/slam/io/laser_log.hpp"
#include "lookahead/slam/io/trajectory_io.hpp"

namespace lookahead::slam {

struct LogCheckOptions {
  /// A gap is a scan period longer than this many median periods and than min_gap, or
  /// longer than max_gap whatever the median (a log sampled sparsely throughout).
  double gap_factor = 5.0;
  double min_gap = 1.0;  ///< [s]
  double max_gap = 5.0;  ///< [s]
  /// An odometry jump: consecutive scans further apart than jump_distance [m] at more than
  /// max_speed [m/s], or turned more than jump_angle [rad] at more than max_turn_rate [rad/s].
  double jump_distance = 0.5;
  double max_speed = 3.0;
  double jump_angle = 0.8;
  double max_turn_rate = 4.0;
  /// Share of no-return readings above which the laser sees almost nothing (warning).
  double max_no_return_share = 0.6;
  /// Scan pairs within this time are the same instant when told apart from time going back [s].
  double stamp_tolerance = 1e-6;
};

enum class Severity { kNote, kWarning, kError };

/// One observation; `code` is stable for scripts and tests (e.g. "duplicate_scans").
struct Finding {
  Severity severity = Severity::kNote;
  std::string code;
  std::string message;
};

struct ScanGap {
  double t = 0.0;        ///< stamp of the scan after the gap [s]
  double seconds = 0.0;  ///< length of the gap [s]
};

struct LogCheck {
  std::string path;
  std::vector<MessageCount> messages;
  std::string scan_source, odometry_source;
  std::size_t scans = 0;
  double first_stamp = 0.0, last_stamp = 0.0;
  double median_period = 0.0;         ///< [s]
  std::vector<ScanGap> largest_gaps;  ///< up to three, longest first, equal ones in time order
  std::size_t long_gaps = 0;          ///< gaps over the threshold
  double gap_threshold = 0.0;         ///< [s]
  std::size_t time_backwards = 0;
  std::size_t duplicate_scans = 0;
  std::size_t odometry_jumps = 0;
  std::size_t beam_count_changes = 0;
  std::size_t fov_changes = 0;
  std::size_t beams_min = 0, beams_max = 0;
  double no_return_share = 0.0;
  double no_return_value = 0.0;      ///< most frequent finite no-return reading (0: none) [m]
  Pose2 laser_offset;                ///< of the first scan
  double laser_offset_spread = 0.0;  ///< largest distance of another scan's offset from it [m]
  std::size_t scans_without_odometry = 0;
  bool odometry_moves = false;
  std::string stopped_early;
  std::vector<Finding> findings;

  [[nodiscard]] double rate_hz() const { return median_period > 0.0 ? 1.0 / median_period : 0.0; }
  /// 0: mapping can proceed; 1: warnings; 2: cannot map.
  [[nodiscard]] int exit_code() const;
};

LogCheck check_log(const LaserLog& log, const LogCheckOptions& options = {});

/// Adds whether `reference` (a corrected log or trajectory) covers the log's scans, on the
/// scans' own clock or on the logger clock, whichever it overlaps more.
void check_reference(LogCheck& check, const LaserLog& log, const std::vector<StampedPose>& reference,
                     const std::string& reference_path);

const char* to_string(Severity s);

}  // namespace lookahead::slam
