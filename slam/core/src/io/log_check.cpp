// SPDX-License-Identifier: MIT
#include "lookahead/slam/io/log_check.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace lookahead::slam {
namespace {

void add(LogCheck& c, Severity s, const char* code, std::string message) {
  c.findings.push_back({s, code, std::move(message)});
}

void check_timing(LogCheck& c, const LaserLog& log, const LogCheckOptions& o) {
  std::vector<double> periods;
  std::vector<ScanGap> gaps;
  double first_back = 0.0;
  for (std::size_t i = 1; i < log.scans.size(); ++i) {
    const double dt = log.scans[i].timestamp - log.scans[i - 1].timestamp;
    if (dt < -o.stamp_tolerance && c.time_backwards++ == 0) first_back = log.scans[i].timestamp;
    periods.push_back(dt);
    gaps.push_back({log.scans[i].timestamp, dt});
  }
  if (!periods.empty()) {
    std::nth_element(periods.begin(), periods.begin() + static_cast<std::ptrdiff_t>(periods.size() / 2), periods.end());
    c.median_period = periods[periods.size() / 2];
  }
  c.gap_threshold = std::min(o.max_gap, std::max(o.min_gap, o.gap_factor * c.median_period));
  std::stable_sort(gaps.begin(), gaps.end(), [](const ScanGap& a, const ScanGap& b) { return a.seconds > b.seconds; });
  for (const ScanGap& g : gaps) c.long_gaps += g.seconds > c.gap_threshold;
  gaps.resize(std::min<std::size_t>(gaps.size(), 3));
  c.largest_gaps = gaps;
  if (c.long_gaps > 0) {
    add(c, Severity::kWarning, "gaps",
        fmt::format("{} gaps between scans longer than {:.2f} s; the longest {:.2f} s before t = {:.3f} s "
                    "(median period {:.3f} s)",
                    c.long_gaps, c.gap_threshold, c.largest_gaps[0].seconds, c.largest_gaps[0].t, c.median_period));
  }
  if (c.time_backwards > 0) {
    add(c, Severity::kWarning, "time_backwards",
        fmt::format("scan stamps go backwards {} times, first at t = {:.6f} s", c.time_backwards, first_back));
  }
}

// What the reader already repaired (odometry_check.hpp): the scans it dropped or re-anchored
// (time going backwards it keeps, and check_timing counts).
void report_repairs(LogCheck& c, const LaserLog& log) {
  if (log.non_finite.count > 0) {
    add(c, Severity::kWarning, "non_finite",
        fmt::format("{} scans with a non-finite pose or time were skipped; first: {}", log.non_finite.count,
                    log.non_finite.first));
  }
  if (log.odometry_jumps.count > 0) {
    c.odometry_jumps += log.odometry_jumps.count;
    add(c, Severity::kWarning, "odometry_jumps",
        fmt::format("{} odometry jumps over max_odometry_step, where the motion model was reset; first: {}",
                    log.odometry_jumps.count, log.odometry_jumps.first));
  }
}

void check_odometry(LogCheck& c, const LaserLog& log, const LogCheckOptions& o) {
  double first_t = 0.0, largest = 0.0;
  for (std::size_t i = 1; i < log.scans.size(); ++i) {
    const Pose2 d = log.scans[i - 1].odometry.between(log.scans[i].odometry);
    if (d.norm() > 0.0 || d.theta != 0.0) c.odometry_moves = true;
    const double dt = std::max(log.scans[i].timestamp - log.scans[i - 1].timestamp, 1e-3);
    const bool leap = d.norm() > o.jump_distance && d.norm() / dt > o.max_speed;
    const bool spin = std::abs(d.theta) > o.jump_angle && std::abs(d.theta) / dt > o.max_turn_rate;
    if (!leap && !spin) continue;
    if (c.odometry_jumps++ == 0) first_t = log.scans[i].timestamp;
    largest = std::max(largest, d.norm());
  }
  if (c.odometry_jumps > 0) {
    add(c, Severity::kWarning, "odometry_jumps",
        fmt::format("odometry jumps {} times between consecutive scans (first at t = {:.3f} s, largest {:.2f} m)",
                    c.odometry_jumps, first_t, largest));
  }
  if (log.scans.size() > 1 && !c.odometry_moves) {
    add(c, Severity::kWarning, "odometry_still", "odometry never changes: the filter gets no motion prior");
  }
  if (c.scans_without_odometry > 0) {
    add(c, Severity::kWarning, "odometry_coverage",
        fmt::format("{} scans have no odometry at their time and are left out", c.scans_without_odometry));
  }
}

void check_geometry(LogCheck& c, const LaserLog& log, const LogCheckOptions& o) {
  const LaserScan& first = log.scans.front();
  c.beams_min = c.beams_max = first.ranges.size();
  c.laser_offset = first.laser_offset;
  std::size_t readings = 0, no_returns = 0;
  std::map<float, std::size_t> no_return_values;
  for (std::size_t i = 0; i < log.scans.size(); ++i) {
    const LaserScan& s = log.scans[i];
    c.beams_min = std::min(c.beams_min, s.ranges.size());
    c.beams_max = std::max(c.beams_max, s.ranges.size());
    c.laser_offset_spread = std::max(c.laser_offset_spread, c.laser_offset.between(s.laser_offset).norm());
    for (std::size_t b = 0; b < s.ranges.size(); ++b) {
      if (s.is_return(b)) continue;
      ++no_returns;
      if (std::isfinite(s.ranges[b]) && s.ranges[b] > 0.0f) ++no_return_values[s.ranges[b]];
    }
    readings += s.ranges.size();
    if (i == 0) continue;
    const LaserScan& p = log.scans[i - 1];
    c.beam_count_changes += s.ranges.size() != p.ranges.size();
    const double fov = s.angle_increment * static_cast<double>(s.ranges.size());
    const double prev = p.angle_increment * static_cast<double>(p.ranges.size());
    c.fov_changes += std::abs(fov - prev) > 1e-4 || std::abs(s.angle_min - p.angle_min) > 1e-4;
  }
  c.no_return_share = readings ? static_cast<double>(no_returns) / static_cast<double>(readings) : 0.0;
  std::size_t best = 0;
  for (const auto& [value, n] : no_return_values) {
    if (n > best) best = n, c.no_return_value = value;
  }
  if (c.beam_count_changes > 0 || c.fov_changes > 0) {
    add(c, Severity::kWarning, "scan_geometry",
        fmt::format("beam count changes {} times ({}..{} beams), field of view or start angle {} times",
                    c.beam_count_changes, c.beams_min, c.beams_max, c.fov_changes));
  }
  const Severity share = c.no_return_share > o.max_no_return_share ? Severity::kWarning : Severity::kNote;
  add(c, share, "no_returns",
      c.no_return_value > 0.0
          ? fmt::format(
                "{:.1f}% of readings are no-returns, most written as {:.2f} m (at or above the {:.2f} m max range)",
                100.0 * c.no_return_share, c.no_return_value, first.max_range)
          : fmt::format("{:.1f}% of readings are no-returns", 100.0 * c.no_return_share));
  add(c, Severity::kNote, "laser_offset",
      fmt::format(
          "laser at x {:.3f} m, y {:.3f} m, yaw {:.2f} deg in the robot frame{}", c.laser_offset.x, c.laser_offset.y,
          c.laser_offset.theta * 180.0 / M_PI,
          c.laser_offset_spread > 1e-3 ? fmt::format(" (varies by up to {:.3f} m)", c.laser_offset_spread) : ""));
}

}  // namespace

const char* to_string(Severity s) {
  switch (s) {
    case Severity::kNote:
      return "note";
    case Severity::kWarning:
      return "warning";
    case Severity::kError:
      return "error";
  }
  return "?";
}

int LogCheck::exit_code() const {
  int code = 0;
  for (const Finding& f : findings) {
    code = std::max(code, f.severity == Severity::kError ? 2 : f.severity == Severity::kWarning ? 1 : 0);
  }
  return code;
}

LogCheck check_log(const LaserLog& log, const LogCheckOptions& options) {
  LogCheck c;
  c.path = log.path;
  c.messages = log.messages;
  c.scan_source = log.scan_source;
  c.odometry_source = log.odometry_source;
  c.scans = log.scans.size();
  c.duplicate_scans = log.duplicate_scans;
  c.scans_without_odometry = log.scans_without_odometry;
  c.stopped_early = log.stopped_early;
  if (log.bad_lines > 0) {
    add(c, Severity::kWarning, "bad_lines",
        fmt::format("{} malformed lines skipped; first: {}", log.bad_lines, log.first_bad_line_message));
  }
  if (!log.stopped_early.empty()) add(c, Severity::kWarning, "stopped_early", log.stopped_early);
  report_repairs(c, log);
  if (log.scans.empty()) {
    add(c, Severity::kError, "no_scans", "no laser scans: nothing to map");
    return c;
  }
  c.first_stamp = log.scans.front().timestamp;
  c.last_stamp = log.scans.back().timestamp;
  if (c.duplicate_scans > 0) {
    add(c, Severity::kNote, "duplicate_scans",
        fmt::format("{} scans appear again in other messages (same ranges); only {} is used", c.duplicate_scans,
                    c.scan_source));
  }
  check_timing(c, log, options);
  check_odometry(c, log, options);
  check_geometry(c, log, options);
  return c;
}

void check_reference(LogCheck& c, const LaserLog& log, const std::vector<StampedPose>& reference,
                     const std::string& reference_path) {
  if (reference.empty() || log.scans.empty()) {
    add(c, Severity::kWarning, "reference", reference_path + ": the reference has no poses");
    return;
  }
  const auto [lo, hi] = std::minmax_element(reference.begin(), reference.end(),
                                            [](const StampedPose& a, const StampedPose& b) { return a.t < b.t; });
  const double r0 = lo->t, r1 = hi->t;
  // CARMEN logs carry two clocks and corrected logs print either: take the one it overlaps.
  const auto overlap = [&](bool logger) {
    const double s0 = logger ? log.scans.front().logger_timestamp : log.scans.front().timestamp;
    const double s1 = logger ? log.scans.back().logger_timestamp : log.scans.back().timestamp;
    return std::min(s1, r1) - std::max(s0, r0);
  };
  const bool logger = overlap(true) > overlap(false);
  std::size_t before = 0, after = 0;
  for (const LaserScan& s : log.scans) {
    const double t = logger ? s.logger_timestamp : s.timestamp;
    before += t < r0;
    after += t > r1;
  }
  const double end = logger ? log.scans.back().logger_timestamp : log.scans.back().timestamp;
  const double start = logger ? log.scans.front().logger_timestamp : log.scans.front().timestamp;
  const char* clock = logger ? "logger" : "scan";
  if (before == 0 && after == 0) {
    add(c, Severity::kNote, "reference", fmt::format("{} covers every scan ({} clock)", reference_path, clock));
    return;
  }
  if (after > 0) {
    add(c, Severity::kWarning, "reference_ends_early",
        fmt::format("{} ends at t = {:.3f} s, {:.1f} s before the log ({} clock): {} scans have no reference pose",
                    reference_path, r1, end - r1, clock, after));
  }
  if (before > 0) {
    add(c, Severity::kWarning, "reference_starts_late",
        fmt::format("{} starts at t = {:.3f} s, {:.1f} s after the log ({} clock): {} scans have no reference pose",
                    reference_path, r0, r0 - start, clock, before));
  }
}

}  // namespace lookahead::slam
