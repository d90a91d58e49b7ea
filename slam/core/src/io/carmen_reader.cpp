// SPDX-License-Identifier: MIT
// CARMEN log reader. Formats as seen in the real logs (shared/data/SOURCES.md section 2):
//   ODOM x y theta tv rv accel ipc host logger
//   FLASER|RLASER n r1..rn x y theta odom_x odom_y odom_theta ipc host logger
//   ROBOTLASER1 type start fov res max acc rem_mode n r1..rn m [rem1..remm]
//               lx ly ltheta rx ry rtheta tv rv fsd ssd [turn_axis] ipc host logger
//   RAWLASER1   type start fov res max acc rem_mode n r1..rn m [rem1..remm] ipc host logger
//   PARAM name value [ipc host logger]
// A log may carry the same scans in several messages (MIT CSAIL: FLASER, ROBOTLASER1 and
// RAWLASER1), so each message kind fills its own stream and one stream is returned:
// FLASER, else ROBOTLASER1, else RAWLASER1, else RLASER.
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <optional>
#include <unordered_set>

#include "lookahead/slam/io/carmen_fields.hpp"
#include "lookahead/slam/io/laser_log.hpp"
#include "lookahead/slam/io/line_reader.hpp"
#include "lookahead/slam/io/odometry_check.hpp"
#include "lookahead/slam/limits/input_limits.hpp"

namespace lookahead::slam {
namespace {

using carmen::Fields;
using limits::kMaxBeams;

struct OdomSample {
  double t;
  Pose2 pose;
};

constexpr std::array<const char*, 4> kStreamNames = {"FLASER", "ROBOTLASER1", "RAWLASER1", "RLASER"};

struct ReaderState {
  std::map<std::string, double> params;
  std::map<std::string, std::size_t> counts;  // lines per message kind
  std::vector<OdomSample> odometry;
  // Streams in order of preference (see file comment).
  std::array<std::vector<LaserScan>, 4> streams;
  std::vector<std::size_t> raw_needs_odometry;  // RAWLASER1 scans get odometry at the end
};

double param_or(const ReaderState& s, const char* name, double fallback) {
  const auto it = s.params.find(name);
  return it == s.params.end() ? fallback : it->second;
}

// Reads n ranges starting at token `first`; nan/inf are accepted as no-returns.
void read_ranges(const Fields& f, std::size_t first, std::size_t n, LaserScan& scan) {
  scan.ranges.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    scan.ranges[i] = static_cast<float>(f.number(first + i, "range", true));
  }
}

// FLASER carries no field of view: 180 deg by convention (GMapping's too), or the PARAM.
// An odd count spans the fov inclusively (361 -> 0.5 deg from -90 to +90), an even count
// exclusively (360 -> 0.5 deg, 180 -> 1 deg).
void flaser_geometry(const ReaderState& s, LaserScan& scan) {
  const double fov = param_or(s, "laser_front_laser_fov", M_PI);
  const std::size_t n = scan.ranges.size();
  const double steps = (n % 2 == 1) ? static_cast<double>(n - 1) : static_cast<double>(n);
  scan.angle_min = -fov / 2.0;
  scan.angle_increment = n > 1 ? fov / steps : 0.0;
}

double ipc_time(const Fields& f) { return f.number(f.size() - 3, "ipc_timestamp"); }
double logger_time(const Fields& f) { return f.number(f.size() - 1, "logger_timestamp"); }

void parse_flaser(const Fields& f, ReaderState& s, const LogReadOptions& o, bool rear) {
  f.require(2, "num_readings");
  const std::size_t n = f.count(1, "num_readings", kMaxBeams);
  f.require(2 + n + 9, "FLASER fields");
  LaserScan scan;
  read_ranges(f, 2, n, scan);
  const std::size_t p = 2 + n;
  const Pose2 laser{f.number(p, "x"), f.number(p + 1, "y"), f.number(p + 2, "theta")};
  scan.odometry = {f.number(p + 3, "odom_x"), f.number(p + 4, "odom_y"),
                   normalize_angle(f.number(p + 5, "odom_theta"))};
  scan.timestamp = ipc_time(f);
  scan.logger_timestamp = logger_time(f);
  // The laser pose on the line already includes the mounting offset: recover it.
  scan.laser_offset = scan.odometry.between(laser);
  if (scan.laser_offset.norm() > 2.0) scan.laser_offset = Pose2{};  // not odometry-based
  const double max_param = rear ? param_or(s, "robot_rear_laser_max", 1e9) : param_or(s, "robot_front_laser_max", 1e9);
  scan.max_range = std::min(o.no_return_range, max_param);
  flaser_geometry(s, scan);
  s.streams[rear ? 3 : 0].push_back(std::move(scan));
}

// Shared head of ROBOTLASER1 and RAWLASER1; returns the token index after the remissions.
std::size_t parse_laser_head(const Fields& f, const LogReadOptions& o, LaserScan& scan) {
  f.require(9, "laser header");
  scan.angle_min = f.number(2, "start_angle");
  const double fov = f.number(3, "fov");
  scan.angle_increment = f.number(4, "angular_res");
  scan.max_range = std::min(o.no_return_range, f.number(5, "max_range"));
  const std::size_t n = f.count(8, "num_readings", kMaxBeams);
  f.require(9 + n + 1, "ranges");
  read_ranges(f, 9, n, scan);
  if (n > 1 &&
      std::abs(scan.angle_increment * static_cast<double>(n - 1) - fov) > 2.0 * std::abs(scan.angle_increment) + 1e-3) {
    // angular_res disagrees with fov: trust fov, as the beam count infers it.
    scan.angle_increment = fov / static_cast<double>(n % 2 == 1 ? n - 1 : n);
  }
  const std::size_t m = f.count(9 + n, "num_remissions", kMaxBeams);
  return 9 + n + 1 + m;
}

void parse_robotlaser(const Fields& f, ReaderState& s, const LogReadOptions& o) {
  LaserScan scan;
  const std::size_t p = parse_laser_head(f, o, scan);
  // Older writers leave out turn_axis: 13 trailing fields instead of 14.
  const std::size_t trailing = f.size() >= p ? f.size() - p : 0;
  if (trailing != 13 && trailing != 14) {
    f.fail("trailing fields", std::to_string(trailing), "expected 13 or 14 after the remissions");
  }
  const Pose2 laser{f.number(p, "laser_x"), f.number(p + 1, "laser_y"), f.number(p + 2, "laser_theta")};
  scan.odometry = {f.number(p + 3, "robot_x"), f.number(p + 4, "robot_y"),
                   normalize_angle(f.number(p + 5, "robot_theta"))};
  scan.laser_offset = scan.odometry.between(laser);
  if (scan.laser_offset.norm() > 2.0) scan.laser_offset = Pose2{};
  scan.timestamp = ipc_time(f);
  scan.logger_timestamp = logger_time(f);
  s.streams[1].push_back(std::move(scan));
}

void parse_rawlaser(const Fields& f, ReaderState& s, const LogReadOptions& o) {
  LaserScan scan;
  const std::size_t p = parse_laser_head(f, o, scan);
  if (f.size() != p + 3) f.fail("trailing fields", std::to_string(f.size() - p), "expected 3");
  scan.timestamp = ipc_time(f);
  scan.logger_timestamp = logger_time(f);
  scan.laser_offset = {param_or(s, "robot_frontlaser_offset", 0.0), 0.0, 0.0};
  s.raw_needs_odometry.push_back(s.streams[2].size());
  s.streams[2].push_back(std::move(scan));
}

void parse_odom(const Fields& f, ReaderState& s) {
  f.require(10, "ODOM fields");
  s.odometry.push_back({ipc_time(f), {f.number(1, "x"), f.number(2, "y"), normalize_angle(f.number(3, "theta"))}});
}

// Logs print the field of view in radians (the MIT CSAIL log: 3.14159); a carmen.ini gives
// it in degrees (180). No laser sees more than a turn, so the two ranges cannot be confused.
double laser_fov_radians(const Fields& f, double v) {
  if (v > 0 && v <= 2 * M_PI) return v;
  if (v > 2 * M_PI && v <= 360) return v * M_PI / 180.0;
  f.fail("laser_front_laser_fov", f.token(2), "not a field of view: (0, 6.2832] rad or (6.2832, 360] deg");
}

void parse_param(const Fields& f, ReaderState& s) {
  f.require(3, "PARAM fields");
  const std::string name(f.token(1));
  if (name == "laser_front_laser_fov") {  // the one PARAM that must be a number: it sets the geometry
    s.params[name] = laser_fov_radians(f, f.number(2, "laser_front_laser_fov"));
    return;
  }
  double v = 0.0;
  const std::string_view t = f.token(2);
  if (std::from_chars(t.data(), t.data() + t.size(), v).ec == std::errc()) s.params[name] = v;
}

void parse_line(const Fields& f, ReaderState& s, const LogReadOptions& o) {
  const std::string_view kind = f.token(0);
  ++s.counts[std::string(kind)];
  if (kind == "FLASER")
    parse_flaser(f, s, o, false);
  else if (kind == "RLASER")
    parse_flaser(f, s, o, true);
  else if (kind == "ROBOTLASER1")
    parse_robotlaser(f, s, o);
  else if (kind == "RAWLASER1")
    parse_rawlaser(f, s, o);
  else if (kind == "ODOM")
    parse_odom(f, s);
  else if (kind == "PARAM")
    parse_param(f, s);
  // Every other message (SYNC, TRUEPOS, NEFF, VERTEX2, EDGE2, ...) carries nothing we use.
}

// Odometry at time t, interpolated linearly between the ODOM messages around it.
Pose2 odometry_at(const std::vector<OdomSample>& odom, double t) {
  if (odom.empty()) return {};
  auto hi = std::lower_bound(odom.begin(), odom.end(), t, [](const OdomSample& a, double v) { return a.t < v; });
  if (hi == odom.begin()) return odom.front().pose;
  if (hi == odom.end()) return odom.back().pose;
  const auto lo = hi - 1;
  const double span = hi->t - lo->t;
  const double a = span > 0 ? (t - lo->t) / span : 0.0;
  const Pose2 d = lo->pose.between(hi->pose);
  return lo->pose.compose({a * d.x, a * d.y, a * d.theta});
}

std::size_t hash_ranges(const std::vector<float>& ranges) {
  std::size_t h = ranges.size();
  for (const float r : ranges) h = h * 1000003u ^ std::hash<float>{}(r);
  return h;
}

// Scans of the other streams whose ranges equal one of the chosen stream's: the same
// measurement written in several message kinds (MIT CSAIL writes each scan three times).
std::size_t count_duplicates(const ReaderState& s, std::size_t chosen) {
  std::unordered_set<std::size_t> seen;
  for (const LaserScan& scan : s.streams[chosen]) seen.insert(hash_ranges(scan.ranges));
  std::size_t n = 0;
  for (std::size_t k = 0; k < s.streams.size(); ++k) {
    if (k == chosen) continue;
    for (const LaserScan& scan : s.streams[k]) n += seen.count(hash_ranges(scan.ranges));
  }
  return n;
}

// RAWLASER1 takes its odometry from ODOM messages: scans outside their span have none.
std::size_t raw_scans_without_odometry(const ReaderState& s) {
  if (s.odometry.empty()) return s.streams[2].size();
  std::size_t n = 0;
  for (const LaserScan& scan : s.streams[2]) {
    n += scan.timestamp < s.odometry.front().t || scan.timestamp > s.odometry.back().t;
  }
  return n;
}

void fill_summary(const ReaderState& s, std::size_t chosen, LaserLog& log) {
  for (const auto& [kind, count] : s.counts) log.messages.push_back({"", kind, count});
  log.scan_source = kStreamNames[chosen];
  log.duplicate_scans = count_duplicates(s, chosen);
  if (chosen == 2) {
    log.odometry_source = "ODOM, interpolated to the scan stamps";
    log.scans_without_odometry = raw_scans_without_odometry(s);
  } else {
    log.odometry_source = std::string(kStreamNames[chosen]) + " odometry fields";
  }
}

/// Reads every line into `state`. A bad last line, or a compressed stream that breaks, is
/// where a truncated file ends: reading stops there and the scans before it are kept
/// (log.stopped_early says where). A bad line with more lines after it is an error, unless
/// skip_bad_lines.
void read_lines(const std::string& path, const LogReadOptions& options, ReaderState& state, LaserLog& log) {
  LineReader reader(path);
  std::string line;
  std::optional<ParseError> pending;  // a bad line, fatal unless it is the last one
  try {
    while (reader.next(line)) {
      const std::size_t first = line.find_first_not_of(" \t");
      if (first == std::string::npos || line[first] == '#') continue;
      if (pending) throw *pending;
      Fields fields(path, reader.line_number(), line);
      try {
        parse_line(fields, state, options);
        for (auto& st : state.streams) {
          if (!st.empty() && st.back().source_line == 0) st.back().source_line = reader.line_number();
        }
      } catch (const ParseError& e) {
        if (!options.skip_bad_lines) {
          pending = e;
          continue;
        }
        if (log.bad_lines++ == 0) log.first_bad_line_message = e.what();
      }
    }
  } catch (const ParseError& e) {
    if (pending || reader.line_number() == 0) throw;
    pending = e;  // a read error of the compressed stream: the file ends here
  }
  log.lines_read = reader.line_number();
  if (!pending) return;
  // A bad last line before any scan leaves nothing to keep: it is the error itself.
  const bool any_scan =
      std::any_of(state.streams.begin(), state.streams.end(), [](const auto& st) { return !st.empty(); });
  if (!any_scan) throw *pending;
  log.stopped_early = pending->what();
}

}  // namespace

LaserLog read_carmen_log(const std::string& path, const LogReadOptions& options) {
  LaserLog log;
  log.path = path;
  ReaderState state;
  read_lines(path, options, state, log);
  std::stable_sort(state.odometry.begin(), state.odometry.end(),
                   [](const OdomSample& a, const OdomSample& b) { return a.t < b.t; });
  for (const std::size_t i : state.raw_needs_odometry) {
    state.streams[2][i].odometry = odometry_at(state.odometry, state.streams[2][i].timestamp);
  }
  for (std::size_t k = 0; k < state.streams.size(); ++k) {
    if (state.streams[k].empty()) continue;
    fill_summary(state, k, log);
    log.scans = std::move(state.streams[k]);
    break;
  }
  check_odometry(log, options);
  return log;
}

LaserLog read_laser_log(const std::string& path, const LogReadOptions& options) {
  const auto ends_with = [&](const std::string& suffix) {
    return path.size() >= suffix.size() && path.compare(path.size() - suffix.size(), suffix.size(), suffix) == 0;
  };
  if (ends_with(".rawlog") || ends_with(".rawlog.gz")) return read_mrpt_rawlog(path, options);
  if (ends_with(".bag")) return read_ros_bag(path, options);
  return read_carmen_log(path, options);
}

}  // namespace lookahead::slam
