// SPDX-License-Identifier: MIT
// `lookahead check LOG|BAG`: what the input holds and what in it would mislead the filter,
// as a table or JSON. Exit 0: mapping can proceed; 1: warnings (named); 2: cannot map.
#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "log_input.hpp"
#include "lookahead/slam/io/log_check.hpp"
#include "lookahead/slam/io/tum_trajectory.hpp"

namespace lookahead::app {
namespace {

struct CheckArgs {
  std::string log;
  std::string reference;
  bool json = false;
  bool skip_bad_lines = false;
  slam::BagReadOptions bag;
};

// A reference is a trajectory file (ours or TUM) or a corrected CARMEN log.
std::vector<slam::StampedPose> read_reference(const std::string& path) {
  const bool trajectory =
      path.size() >= 4 && (path.substr(path.size() - 4) == ".txt" || path.substr(path.size() - 4) == ".tum");
  if (trajectory) return slam::read_any_trajectory(path);
  std::vector<slam::StampedPose> ref;
  for (const auto& s : slam::read_laser_log(path).scans) ref.push_back({s.timestamp, s.odometry});
  return ref;
}

nlohmann::json to_json(const slam::LogCheck& c) {
  nlohmann::json messages = nlohmann::json::array();
  for (const auto& m : c.messages) messages.push_back({{"topic", m.topic}, {"type", m.type}, {"count", m.count}});
  nlohmann::json gaps = nlohmann::json::array();
  for (const auto& g : c.largest_gaps) gaps.push_back({{"t", g.t}, {"seconds", g.seconds}});
  nlohmann::json findings = nlohmann::json::array();
  for (const auto& f : c.findings)
    findings.push_back({{"severity", slam::to_string(f.severity)}, {"code", f.code}, {"message", f.message}});
  return {{"path", c.path},
          {"messages", messages},
          {"scan_source", c.scan_source},
          {"odometry_source", c.odometry_source},
          {"scans", c.scans},
          {"first_stamp", c.first_stamp},
          {"last_stamp", c.last_stamp},
          {"median_period_s", c.median_period},
          {"rate_hz", c.rate_hz()},
          {"largest_gaps", gaps},
          {"long_gaps", c.long_gaps},
          {"gap_threshold_s", c.gap_threshold},
          {"time_backwards", c.time_backwards},
          {"duplicate_scans", c.duplicate_scans},
          {"odometry_jumps", c.odometry_jumps},
          {"beam_count_changes", c.beam_count_changes},
          {"fov_changes", c.fov_changes},
          {"beams_min", c.beams_min},
          {"beams_max", c.beams_max},
          {"no_return_share", c.no_return_share},
          {"no_return_value_m", c.no_return_value},
          {"laser_offset", {c.laser_offset.x, c.laser_offset.y, c.laser_offset.theta}},
          {"scans_without_odometry", c.scans_without_odometry},
          {"odometry_moves", c.odometry_moves},
          {"stopped_early", c.stopped_early},
          {"findings", findings},
          {"exit_code", c.exit_code()}};
}

void print_table(const slam::LogCheck& c) {
  fmt::print("{}\n", c.path);
  fmt::print("  {:<34} {:<28} {:>8}\n", "topic / message", "type", "count");
  for (const auto& m : c.messages)
    fmt::print("  {:<34} {:<28} {:>8}\n", m.topic.empty() ? m.type : m.topic, m.type, m.count);
  fmt::print("  scans from {}: {} over {:.1f} s, {:.2f} Hz (median period {:.3f} s)\n", c.scan_source, c.scans,
             c.last_stamp - c.first_stamp, c.rate_hz(), c.median_period);
  for (const auto& g : c.largest_gaps) fmt::print("  gap {:.3f} s before t = {:.3f} s\n", g.seconds, g.t);
  fmt::print("  beams {}..{}, no-returns {:.1f}%, odometry from {}\n", c.beams_min, c.beams_max,
             100.0 * c.no_return_share, c.odometry_source);
  for (const auto& f : c.findings) fmt::print("  {:<7} {:<22} {}\n", slam::to_string(f.severity), f.code, f.message);
  fmt::print("  verdict: {}\n", c.exit_code() == 0   ? "can map"
                                : c.exit_code() == 1 ? "can map, with the warnings above"
                                                     : "cannot map");
}

int run_check(const CheckArgs& a) {
  slam::LogCheck check;
  check.path = a.log;
  try {
    slam::LogReadOptions read;
    read.skip_bad_lines = a.skip_bad_lines;
    read.bag = a.bag;
    const slam::LaserLog log = slam::read_laser_log(a.log, read);
    check = slam::check_log(log);
    if (!a.reference.empty()) slam::check_reference(check, log, read_reference(a.reference), a.reference);
  } catch (const std::exception& e) {
    check.findings.push_back({slam::Severity::kError, "unreadable", e.what()});
  }
  if (a.json) {
    fmt::print("{}\n", to_json(check).dump(2));
  } else {
    print_table(check);
  }
  return check.exit_code();
}

}  // namespace

Run add_check_command(CLI::App& app) {
  auto args = std::make_shared<CheckArgs>();
  app.add_option("log", args->log, "CARMEN log, MRPT .rawlog or ROS1 .bag")->required();
  app.add_option("--reference", args->reference,
                 "corrected log or trajectory (.txt/.tum): report the scans it does not cover");
  app.add_flag("--json", args->json, "print the report as JSON");
  app.add_flag("--skip-bad-lines", args->skip_bad_lines, "count and skip malformed log lines");
  add_bag_options(app, args->bag);
  return [args] { return run_check(*args); };
}

}  // namespace lookahead::app
