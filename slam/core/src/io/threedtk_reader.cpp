// SPDX-License-Identifier: MIT
#include "lookahead/slam/io/threedtk_reader.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>

#include "lookahead/slam/io/line_reader.hpp"
#include "lookahead/slam/io/parse_error.hpp"

namespace lookahead::slam {
namespace {

constexpr double kCentimetre = 0.01;

// 3DTK (x right, y up, z forward; left-handed) -> lookahead (x forward, y left, z up).
Eigen::Matrix3d from_3dtk() {
  Eigen::Matrix3d p;
  p << 0, 0, 1, -1, 0, 0, 0, 1, 0;
  return p;
}

/// The three numbers of a line; more columns (reflectance, colour) are ignored.
Eigen::Vector3d three_numbers(const std::string& line, const std::string& file, std::size_t n,
                              const char* const names[3]) {
  std::istringstream in(line);
  Eigen::Vector3d v;
  for (int i = 0; i < 3; ++i) {
    std::string token;
    if (!(in >> token)) throw ParseError(file, n, names[i], "", "missing value");
    char* end = nullptr;
    const double x = std::strtod(token.c_str(), &end);
    if (end != token.c_str() + token.size() || !std::isfinite(x)) {
      throw ParseError(file, n, names[i], token, "not a finite number");
    }
    v[i] = x;
  }
  return v;
}

Pose3 read_pose(const std::string& path) {
  static const char* const kPosition[3] = {"x", "y", "z"};
  static const char* const kAngles[3] = {"theta_x", "theta_y", "theta_z"};
  LineReader reader(path);
  std::string line;
  Eigen::Vector3d values[2];
  int found = 0;
  while (found < 2 && reader.next(line)) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    values[found] = three_numbers(line, path, reader.line_number(), found == 0 ? kPosition : kAngles);
    ++found;
  }
  if (found < 2) throw ParseError(path, reader.line_number(), found == 0 ? "x" : "theta_x", "", "pose file ends early");
  const Eigen::Vector3d a = values[1] * (M_PI / 180.0);
  const Eigen::Matrix3d r3 =
      (Eigen::AngleAxisd(a.y(), Eigen::Vector3d::UnitY()) * Eigen::AngleAxisd(a.x(), Eigen::Vector3d::UnitX()) *
       Eigen::AngleAxisd(a.z(), Eigen::Vector3d::UnitZ()))
          .toRotationMatrix();
  const Eigen::Matrix3d p = from_3dtk();
  Pose3 pose = Pose3::Identity();
  pose.linear() = p * r3 * p.transpose();
  pose.translation() = p * values[0] * kCentimetre;
  return pose;
}

}  // namespace

RangeSweep read_3dtk_scan(const std::string& scan_path, const std::string& pose_path, const ThreeDtkOptions& options) {
  if (options.point_step < 1) throw std::invalid_argument("3dtk: point_step must be >= 1");
  static const char* const kPoint[3] = {"x", "y", "z"};
  RangeSweep sweep;
  sweep.odometry = read_pose(pose_path);
  const Eigen::Matrix3d p = from_3dtk();
  LineReader reader(scan_path);
  std::string line;
  std::size_t index = 0;
  while (reader.next(line)) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    const Eigen::Vector3d point = p * three_numbers(line, scan_path, reader.line_number(), kPoint) * kCentimetre;
    if (index++ % static_cast<std::size_t>(options.point_step) != 0) continue;
    const double range = point.norm();
    if (range <= 0.0) continue;  // a point at the sensor says nothing
    sweep.rays.push_back({Eigen::Vector3d::Zero(), point, range < options.no_return_range});
  }
  return sweep;
}

RangeLog3 read_3dtk_folder(const std::string& folder, const ThreeDtkOptions& options) {
  RangeLog3 log;
  log.source = folder;
  for (int i = 0;; ++i) {
    char name[16];
    std::snprintf(name, sizeof name, "scan%03d", i);
    const std::filesystem::path base = std::filesystem::path(folder) / name;
    const std::string scan = base.string() + ".3d", pose = base.string() + ".pose";
    if (!std::filesystem::exists(scan)) break;
    RangeSweep sweep = read_3dtk_scan(scan, pose, options);
    sweep.time = i;  // 3DTK scans carry no time stamps: one per second, in order
    log.sweeps.push_back(std::move(sweep));
  }
  if (log.sweeps.empty())
    throw ParseError(folder + "/scan000.3d", 0, "", "", "no 3DTK scans (scan000.3d) in the folder");
  return log;
}

}  // namespace lookahead::slam
