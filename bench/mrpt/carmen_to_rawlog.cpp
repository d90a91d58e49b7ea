// SPDX-License-Identifier: MIT
// carmen_to_rawlog: CARMEN log -> MRPT rawlog of action/observation pairs, so MRPT's
// rbpf-slam can run on the same logs as lookahead (see run_mrpt_rbpf.sh).
//
// Why not MRPT's carmen2rawlog: its rawlog has no odometry actions (rbpf-slam crashes on
// it), stamps every observation with the same time, takes CSAIL's 81.91 m no-returns as
// hits and gives a 180-beam FLASER a 90 deg aperture (shared/BASELINES.md).
//
// Scans come from FLASER lines; from ROBOTLASER1 only when the log has no FLASER (CSAIL
// holds every scan as FLASER, ROBOTLASER1 and RAWLASER1). Beam geometry matches
// slam/src/io/carmen_reader.cpp, so both systems see the same rays.
//
// Usage: carmen_to_rawlog IN.log OUT.rawlog [--every K] [--scans TABLE.txt]
//   --every K   keep every K-th scan (odometry increments still span the skipped ones)
//   --scans F   also write one line per kept scan: "index ipc_ts odom_x odom_y odom_theta"
#include <mrpt/core/Clock.h>
#include <mrpt/io/CFileOutputStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/serialization/CArchive.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

constexpr double kMaxRange = 80.0;  // readings at or past this are no-returns (CSAIL: 81.91)

// One whitespace-split line, with errors that name file:line and the field.
struct Line {
  std::string file;
  std::size_t number = 0;
  std::vector<std::string> tok;

  [[noreturn]] void fail(const std::string& field, const std::string& why) const {
    throw std::runtime_error(file + ":" + std::to_string(number) + ": field '" + field + "': " + why);
  }
  const std::string& at(std::size_t i, const std::string& field) const {
    if (i >= tok.size()) fail(field, "missing (line has " + std::to_string(tok.size()) + ")");
    return tok[i];
  }
  double num(std::size_t i, const std::string& field) const {
    const std::string& s = at(i, field);
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    if (end == s.c_str() || *end != '\0') fail(field, "not a number: '" + s + "'");
    return v;
  }
  std::size_t count(std::size_t i, const std::string& field) const {
    const double v = num(i, field);
    if (v < 0 || v > 100000 || v != std::floor(v)) fail(field, "bad count: " + tok[i]);
    return static_cast<std::size_t>(v);
  }
};

struct Scan {
  std::vector<double> ranges;
  double start_angle = 0;  // angle of the first beam, rad, laser frame
  double increment = 0;    // rad between beams
  mrpt::poses::CPose2D odometry;
  mrpt::poses::CPose2D laser_offset;  // laser in the robot frame
  double ipc_ts = 0;
};

// Odd counts span the fov inclusively (361 -> 0.5 deg, -90..+90), even ones exclusively
// (360 -> 0.5 deg, 180 -> 1 deg, -90..+89), as GMapping and our reader take them.
double beam_increment(double fov, std::size_t n) {
  if (n < 2) return 0;
  return fov / static_cast<double>(n % 2 == 1 ? n - 1 : n);
}

Scan parse_flaser(const Line& l, double frontlaser_offset) {
  Scan s;
  const std::size_t n = l.count(1, "num_readings");
  for (std::size_t i = 0; i < n; ++i) s.ranges.push_back(l.num(2 + i, "range"));
  const std::size_t p = 2 + n;  // x y theta odom_x odom_y odom_theta ipc host logger
  if (l.tok.size() != p + 9)
    l.fail("FLASER fields", "expected " + std::to_string(p + 9) + " tokens, got " + std::to_string(l.tok.size()));
  s.odometry = {l.num(p + 3, "odom_x"), l.num(p + 4, "odom_y"), l.num(p + 5, "odom_theta")};
  s.ipc_ts = l.num(p + 6, "ipc_timestamp");
  s.start_angle = -M_PI / 2;  // FLASER carries no fov: 180 deg by convention
  s.increment = beam_increment(M_PI, n);
  s.laser_offset = {frontlaser_offset, 0, 0};
  return s;
}

Scan parse_robotlaser(const Line& l) {
  Scan s;
  s.start_angle = l.num(2, "start_angle");
  const double fov = l.num(3, "fov");
  const std::size_t n = l.count(8, "num_readings");
  for (std::size_t i = 0; i < n; ++i) s.ranges.push_back(l.num(9 + i, "range"));
  s.increment = beam_increment(fov, n);
  const std::size_t m = l.count(9 + n, "num_remissions");
  const std::size_t p = 10 + n + m;  // laser_x .. robot_theta tv rv fsd ssd [turn_axis] ipc..
  const std::size_t trailing = l.tok.size() > p ? l.tok.size() - p : 0;
  if (trailing != 13 && trailing != 14)
    l.fail("ROBOTLASER1 fields", "expected 13 or 14 after the remissions, got " + std::to_string(trailing));
  const mrpt::poses::CPose2D laser{l.num(p, "laser_x"), l.num(p + 1, "laser_y"), l.num(p + 2, "laser_theta")};
  s.odometry = {l.num(p + 3, "robot_x"), l.num(p + 4, "robot_y"), l.num(p + 5, "robot_theta")};
  s.ipc_ts = l.num(l.tok.size() - 3, "ipc_timestamp");
  // The line carries both poses, so the mounting offset is exact here (no PARAM needed).
  s.laser_offset = laser - s.odometry;
  return s;
}

// MRPT spreads a scan symmetrically over [-aperture/2, aperture/2] around the sensor yaw,
// so an asymmetric CARMEN scan (-90..+89 deg) becomes a rotated sensor pose.
mrpt::obs::CObservation2DRangeScan to_observation(const Scan& s) {
  mrpt::obs::CObservation2DRangeScan obs;
  obs.sensorLabel = "LASER";
  obs.timestamp = mrpt::Clock::fromDouble(s.ipc_ts);
  obs.rightToLeft = true;
  obs.maxRange = static_cast<float>(kMaxRange);
  const std::size_t n = s.ranges.size();
  const double aperture = s.increment * static_cast<double>(n > 0 ? n - 1 : 0);
  obs.aperture = static_cast<float>(aperture);
  const double centre = s.start_angle + aperture / 2;
  obs.sensorPose = mrpt::poses::CPose3D(s.laser_offset.x(), s.laser_offset.y(), 0, s.laser_offset.phi() + centre, 0, 0);
  obs.resizeScan(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double r = s.ranges[i];
    obs.setScanRange(i, static_cast<float>(r));
    // <= 0 is the SICK's "no echo" on some logs; >= kMaxRange is a no-return.
    obs.setScanRangeValidity(i, r > 0 && r < kMaxRange);
  }
  return obs;
}

std::vector<Line> read_lines(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open");
  std::vector<Line> lines;
  std::string text;
  for (std::size_t number = 1; std::getline(in, text); ++number) {
    Line l{path, number, {}};
    std::istringstream ss(text);
    for (std::string t; ss >> t;) l.tok.push_back(t);
    if (!l.tok.empty()) lines.push_back(std::move(l));
  }
  return lines;
}

std::vector<Scan> read_scans(const std::string& path) {
  const std::vector<Line> lines = read_lines(path);
  bool has_flaser = false;
  double offset = 0;  // robot_frontlaser_offset: x of the front laser on the robot, m
  for (const Line& l : lines) {
    has_flaser = has_flaser || l.tok[0] == "FLASER";
    if (l.tok[0] == "PARAM" && l.at(1, "name") == "robot_frontlaser_offset")
      offset = l.num(2, "robot_frontlaser_offset");
  }
  std::vector<Scan> scans;
  for (const Line& l : lines) {
    if (has_flaser && l.tok[0] == "FLASER") scans.push_back(parse_flaser(l, offset));
    if (!has_flaser && l.tok[0] == "ROBOTLASER1") scans.push_back(parse_robotlaser(l));
  }
  return scans;
}

void write_rawlog(const std::vector<Scan>& scans, std::size_t every, const std::string& out, const std::string& table) {
  mrpt::io::CFileOutputStream file;
  if (!file.open(out)) throw std::runtime_error(out + ": cannot write");
  auto arch = mrpt::serialization::archiveFrom(file);
  std::ofstream tab;
  if (!table.empty()) {
    tab.open(table);
    if (!tab) throw std::runtime_error(table + ": cannot write");
    tab << std::fixed << std::setprecision(6);  // CARMEN's own precision
  }
  const mrpt::obs::CActionRobotMovement2D::TMotionModelOptions motion;  // MRPT's defaults
  const Scan* prev = nullptr;
  for (std::size_t i = 0; i < scans.size(); i += every) {
    const Scan& s = scans[i];
    // First scan: zero motion, so the map starts at the origin like MRPT's own path.
    const mrpt::poses::CPose2D delta = prev ? s.odometry - prev->odometry : mrpt::poses::CPose2D();
    mrpt::obs::CActionRobotMovement2D move;
    move.computeFromOdometry(delta, motion);
    move.timestamp = mrpt::Clock::fromDouble(s.ipc_ts);
    mrpt::obs::CActionCollection actions;
    actions.insert(move);
    mrpt::obs::CSensoryFrame frame;
    frame.insert(mrpt::obs::CObservation2DRangeScan::Create(to_observation(s)));
    arch << actions << frame;
    if (tab.is_open())
      tab << i << ' ' << s.ipc_ts << ' ' << s.odometry.x() << ' ' << s.odometry.y() << ' ' << s.odometry.phi() << '\n';
    prev = &s;
  }
}

}  // namespace

int main(int argc, char** argv) {
  try {
    std::vector<std::string> pos;
    std::size_t every = 1;
    std::string table;
    for (int i = 1; i < argc; ++i) {
      const std::string a = argv[i];
      if ((a == "--every" || a == "--scans") && i + 1 < argc) {
        const std::string v = argv[++i];
        if (a == "--scans")
          table = v;
        else if ((every = std::strtoul(v.c_str(), nullptr, 10)) == 0)
          throw std::runtime_error("--every: need a positive integer, got '" + v + "'");
      } else {
        pos.push_back(a);
      }
    }
    if (pos.size() != 2) {
      std::cerr << "usage: carmen_to_rawlog IN.log OUT.rawlog [--every K] [--scans TABLE]\n";
      return 2;
    }
    const std::vector<Scan> scans = read_scans(pos[0]);
    if (scans.empty()) throw std::runtime_error(pos[0] + ": no FLASER or ROBOTLASER1 scans");
    write_rawlog(scans, every, pos[1], table);
    std::cout << pos[0] << ": " << scans.size() << " scans, wrote " << (scans.size() + every - 1) / every << " to "
              << pos[1] << "\n";
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "carmen_to_rawlog: " << e.what() << "\n";
    return 1;
  }
}
