// SPDX-License-Identifier: MIT
// Writes a CARMEN log with *synthetic* odometry from a log of real scans with corrected poses
// (shared/data/derived-flirtlib: VERTEX2 poses, each followed by its ROBOTLASER1 scan), using
// the drift model of lookahead/slam/eval/synthetic_odometry.hpp. Every figure computed from
// its output is "real scans, synthetic odometry".
//   usage: synth_odometry IN.log OUT.log [--seed N] [--kt 0.03] [--kr 0.05] [--krt 0.01]
//                         [--kb 0.005] [--kbw 0.001]
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "lookahead/slam/eval/synthetic_odometry.hpp"
#include "lookahead/slam/geometry/pose2.hpp"
#include "lookahead/slam/io/line_reader.hpp"
#include "lookahead/slam/io/parse_error.hpp"

namespace {

using lookahead::slam::Pose2;

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
      if (t.size() < 5)
        throw lookahead::slam::ParseError(path, reader.line_number(), "VERTEX2", line, "needs id x y theta");
      truth = {std::stod(t[2]), std::stod(t[3]), lookahead::slam::normalize_angle(std::stod(t[4]))};
      have_truth = true;
    } else if (t[0] == "ROBOTLASER1") {
      if (!have_truth)
        throw lookahead::slam::ParseError(path, reader.line_number(), "ROBOTLASER1", "", "scan before any VERTEX2");
      out.push_back({truth, std::move(t)});
    }
  }
  return out;
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
  lookahead::slam::OdometryDriftModel m;
  app.add_option("in", in, "derived-flirtlib log (VERTEX2 + ROBOTLASER1)")->required();
  app.add_option("out", out, "CARMEN log to write")->required();
  app.add_option("--seed", m.seed)->capture_default_str();
  app.add_option("--kt", m.k_t, "translation noise per metre")->capture_default_str();
  app.add_option("--kr", m.k_r, "rotation noise per radian")->capture_default_str();
  app.add_option("--krt", m.k_rt, "rotation noise per metre [rad/m]")->capture_default_str();
  app.add_option("--kb", m.k_b, "std of the heading bias [rad/m]")->capture_default_str();
  app.add_option("--kbw", m.k_bw, "random walk of the bias per metre")->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  try {
    const auto records = read_records(in);
    if (records.empty()) throw std::runtime_error(in + ": no ROBOTLASER1 scans");
    std::vector<Pose2> truth;
    for (const auto& r : records) truth.push_back(r.truth);
    const auto odom = lookahead::slam::synthesize_odometry(truth, m);
    std::ofstream o(out);
    o << "# Real scans, SYNTHETIC odometry: written by lookahead bench/tools/synth_odometry\n"
      << fmt::format("# from {} seed {} kt {} kr {} krt {} kb {} kbw {}\n", in, m.seed, m.k_t, m.k_r, m.k_rt, m.k_b,
                     m.k_bw);
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
