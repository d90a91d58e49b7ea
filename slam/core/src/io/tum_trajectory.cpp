// SPDX-License-Identifier: MIT
#include "lookahead/slam/io/tum_trajectory.hpp"

#include <fmt/format.h>

#include <cmath>
#include <fstream>

#include "lookahead/slam/io/carmen_fields.hpp"
#include "lookahead/slam/io/line_reader.hpp"

namespace lookahead::slam {
namespace {

// A unit quaternion within this of norm 1; TUM files print 4-6 decimals, so 1e-2 leaves
// room for rounding while rejecting a swapped column or a zero quaternion.
constexpr double kQuaternionNormTolerance = 1e-2;

StampedPose parse_tum(const carmen::Fields& f) {
  if (f.size() != 8) f.fail("fields", std::to_string(f.size()), "expected 'timestamp tx ty tz qx qy qz qw'");
  const double qx = f.number(4, "qx"), qy = f.number(5, "qy"), qz = f.number(6, "qz"), qw = f.number(7, "qw");
  const double norm = std::sqrt(qx * qx + qy * qy + qz * qz + qw * qw);
  if (std::abs(norm - 1.0) > kQuaternionNormTolerance) {
    f.fail("quaternion", fmt::format("{} {} {} {}", qx, qy, qz, qw), fmt::format("norm {} is not 1", norm));
  }
  f.number(3, "tz");  // checked, not used: the filter is planar
  // Yaw of R(q) in a form that does not need |q| = 1.
  const double yaw = std::atan2(2.0 * (qw * qz + qx * qy), qw * qw + qx * qx - qy * qy - qz * qz);
  return {f.number(0, "timestamp"), {f.number(1, "tx"), f.number(2, "ty"), normalize_angle(yaw)}};
}

// Column count of the first line that is not blank or a comment; 0 for an empty file.
std::size_t first_data_columns(const std::string& path) {
  LineReader reader(path);
  std::string line;
  while (reader.next(line)) {
    const std::size_t first = line.find_first_not_of(" \t");
    if (first == std::string::npos || line[first] == '#') continue;
    return carmen::Fields(path, reader.line_number(), line).size();
  }
  return 0;
}

}  // namespace

void write_tum_trajectory(const std::string& path, const std::vector<StampedPose>& poses) {
  std::ofstream out(path);
  if (!out) throw ParseError(path, 0, "", "", "cannot write file");
  out << "# timestamp tx ty tz qx qy qz qw\n";
  for (const StampedPose& s : poses) {
    out << fmt::format("{:.6f} {:.6f} {:.6f} 0 0 0 {:.9f} {:.9f}\n", s.t, s.pose.x, s.pose.y,
                       std::sin(0.5 * s.pose.theta), std::cos(0.5 * s.pose.theta));
  }
  if (!out) throw ParseError(path, 0, "", "", "write failed");
}

std::vector<StampedPose> read_tum_trajectory(const std::string& path) {
  std::vector<StampedPose> poses;
  LineReader reader(path);
  std::string line;
  while (reader.next(line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();  // files written on Windows
    const std::size_t first = line.find_first_not_of(" \t");
    if (first == std::string::npos || line[first] == '#') continue;
    poses.push_back(parse_tum(carmen::Fields(path, reader.line_number(), line)));
  }
  return poses;
}

bool is_tum_trajectory(const std::string& path) { return first_data_columns(path) == 8; }

std::vector<StampedPose> read_any_trajectory(const std::string& path) {
  return is_tum_trajectory(path) ? read_tum_trajectory(path) : read_trajectory(path);
}

}  // namespace lookahead::slam
