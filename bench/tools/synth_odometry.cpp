// SPDX-License-Identifier: MIT
// Writes a CARMEN log with *synthetic* odometry from a log of real scans with corrected poses
// (shared/data/derived-flirtlib: VERTEX2 poses, each followed by its ROBOTLASER1 scan).
// Every figure computed from its output is "real scans, synthetic odometry".
//
// Drift model (seeded; Pioneer-like magnitudes). For consecutive true poses a, b let
// d = a^-1 (+) b = (dx, dy, dth) and s = |(dx, dy)|. The odometry increment is
//   dx' = dx + N(0, (k_t s)^2)
//   dy' = dy + N(0, (k_t s)^2)
//   dth' = dth + N(0, (k_r |dth| + k_rt s)^2) + beta s
// with a heading bias beta [rad/m] drawn once per run from N(0, k_b^2) and then drifting
// as a random walk with step N(0, (k_bw s)^2), and the odometry pose integrates the
// increments from the first true pose.
//   usage: synth_odometry IN.log OUT.log [--seed N] [--kt 0.03] [--kr 0.05] [--krt 0.01]
//                         [--kb 0.005] [--kbw 0.001]
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "lookahead/slam/geometry/pose2.hpp"
#include "lookahead/slam/io/line_reader.hpp"
#include "lookahead/slam/io/parse_error.hpp"

namespace {

using lookahead::slam::Pose2;

struct DriftModel {
  double kt = 0.03, kr = 0.05, krt = 0.01, kb = 0.005, kbw = 0.001;
  std::uint64_t seed = 1;
};

struct Record {
  Pose2 truth;
  std::vector<std::string> scan_fields;  // ROBOTLASER1 tokens, poses to be replaced
};

std::vector<std::string> split(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> t;
  for (std::string s; in >> s;) t.push_back(s);
  return t;
}

std::vector<Record> read_records(const std::string& path) {
  lookahead::slam::LineReader reader(path);
  std::vector<Record> out;
  Pose2 truth;
  bool have_truth = false;
  std::string line;
  while (reader.next(line)) {
    auto t = split(line);
    if (t.empty()) continue;
    if (t[0] == "VERTEX2") {
      if (t.size() < 5) throw lookahead::slam::ParseError(path, reader.line_number(), "VERTEX2", line, "needs id x y theta");
      truth = {std::stod(t[2]), std::stod(t[3]), lookahead::slam::normalize_angle(std::stod(t[4]))};
      have_truth = true;
    } else if (t[0] == "ROBOTLASER1") {
      if (!have_truth) throw lookahead::slam::ParseError(path, reader.line_number(), "ROBOTLASER1", "", "scan before any VERTEX2");
      out.push_back({truth, std::move(t)});
    }
  }
  return out;
}

std::vector<Pose2> synthesize(const std::vector<Record>& records, const DriftModel& m) {
  std::mt19937_64 rng(m.seed);
  std::normal_distribution<double> n(0.0, 1.0);
  double beta = m.kb * n(rng);
  std::vector<Pose2> odom{records.front().truth};
  for (std::size_t i = 1; i < records.size(); ++i) {
    const Pose2 d = records[i - 1].truth.between(records[i].truth);
    const double s = d.norm();
    beta += m.kbw * s * n(rng);
    const Pose2 noisy{d.x + m.kt * s * n(rng), d.y + m.kt * s * n(rng),
                      d.theta + (m.kr * std::abs(d.theta) + m.krt * s) * n(rng) + beta * s};
    odom.push_back(odom.back().compose(noisy));
  }
  return odom;
}

// ROBOTLASER1 with the laser and robot poses replaced by the synthetic odometry (laser
// mounted at the robot origin, as the corrected poses of these logs are laser poses).
std::string scan_line(std::vector<std::string> t, const Pose2& o) {
  const std::size_t n = std::stoul(t[8]);
  const std::size_t m = std::stoul(t[9 + n]);
  const std::size_t p = 9 + n + 1 + m;
  const std::string pose = fmt::format("{:.6f} {:.6f} {:.6f}", o.x, o.y, o.theta);
  std::ostringstream out;
  for (std::size_t i = 0; i < p; ++i) out << t[i] << ' ';
  out << pose << ' ' << pose;
  for (std::size_t i = p + 6; i < t.size(); ++i) out << ' ' << t[i];
  return out.str();
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"CARMEN log with synthetic odometry from scans with corrected poses"};
  std::string in, out;
  DriftModel m;
  app.add_option("in", in, "derived-flirtlib log (VERTEX2 + ROBOTLASER1)")->required();
  app.add_option("out", out, "CARMEN log to write")->required();
  app.add_option("--seed", m.seed)->capture_default_str();
  app.add_option("--kt", m.kt, "translation noise per metre")->capture_default_str();
  app.add_option("--kr", m.kr, "rotation noise per radian")->capture_default_str();
  app.add_option("--krt", m.krt, "rotation noise per metre [rad/m]")->capture_default_str();
  app.add_option("--kb", m.kb, "std of the heading bias [rad/m]")->capture_default_str();
  app.add_option("--kbw", m.kbw, "random walk of the bias per metre")->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  try {
    const auto records = read_records(in);
    if (records.empty()) throw std::runtime_error(in + ": no ROBOTLASER1 scans");
    const auto odom = synthesize(records, m);
    std::ofstream o(out);
    o << "# Real scans, SYNTHETIC odometry: written by lookahead bench/tools/synth_odometry\n"
      << fmt::format("# from {} seed {} kt {} kr {} krt {} kb {} kbw {}\n", in, m.seed, m.kt, m.kr, m.krt, m.kb, m.kbw);
    for (std::size_t i = 0; i < records.size(); ++i) {
      const auto& t = records[i].scan_fields;
      const std::string stamp = t[t.size() - 3] + " synth " + t.back();
      o << fmt::format("ODOM {:.6f} {:.6f} {:.6f} 0 0 0 {}\n", odom[i].x, odom[i].y, odom[i].theta, stamp);
      o << scan_line(t, odom[i]) << "\n";
    }
    fmt::print("{}: {} scans, odometry drift seed {}\n", out, records.size(), m.seed);
  } catch (const std::exception& e) {
    fmt::print(stderr, "synth_odometry: {}\n", e.what());
    return 1;
  }
  return 0;
}
