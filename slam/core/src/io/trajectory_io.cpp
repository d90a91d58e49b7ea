// SPDX-License-Identifier: MIT
#include "lookahead/slam/io/trajectory_io.hpp"

#include <fmt/format.h>

#include <fstream>

#include "lookahead/slam/io/carmen_fields.hpp"
#include "lookahead/slam/io/line_reader.hpp"

namespace lookahead::slam {

void write_trajectory(const std::string& path, const std::vector<StampedPose>& poses) {
  std::ofstream out(path);
  if (!out) throw ParseError(path, 0, "", "", "cannot write file");
  out << "# timestamp x y theta\n";
  for (const StampedPose& s : poses) {
    out << fmt::format("{:.6f} {:.6f} {:.6f} {:.6f}\n", s.t, s.pose.x, s.pose.y, s.pose.theta);
  }
}

std::vector<StampedPose> read_trajectory(const std::string& path) {
  std::vector<StampedPose> poses;
  LineReader reader(path);
  std::string line;
  while (reader.next(line)) {
    const std::size_t first = line.find_first_not_of(" \t");
    if (first == std::string::npos || line[first] == '#') continue;
    const carmen::Fields f(path, reader.line_number(), line);
    if (f.size() != 4) f.fail("fields", std::to_string(f.size()), "expected 'timestamp x y theta'");
    poses.push_back(
        {f.number(0, "timestamp"), {f.number(1, "x"), f.number(2, "y"), normalize_angle(f.number(3, "theta"))}});
  }
  return poses;
}

}  // namespace lookahead::slam
