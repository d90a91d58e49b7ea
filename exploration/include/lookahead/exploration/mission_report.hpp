// SPDX-License-Identifier: MIT
// The figures of a finished mission, and the files a run writes: map.pgm/.yaml, map.png,
// coverage.png, trajectory.txt and run.json.
#pragma once

#include <array>
#include <string>

#include "lookahead/exploration/mission.hpp"
#include "lookahead/exploration/prediction_summary.hpp"

namespace lookahead::exploration {

struct MissionSummary {
  std::string world, strategy, pose_source, status;
  std::uint64_t seed = 0;
  int particles = 0;
  double simulated_time = 0.0, path_length = 0.0, coverage = 0.0;
  std::array<Milestone, 3> milestones{};  ///< 90, 95, 99 % coverage
  double reachable_area_m2 = 0.0;
  MapQuality quality;
  double slam_position_error_mean = 0.0;  ///< |estimate - truth| over the run [m] (SLAM only)
  double slam_position_error_final = 0.0;
  MissionStatistics statistics;
  double wall_time = 0.0, real_time_factor = 0.0;
  PredictionSummary prediction;  ///< P-SLAM look-ahead mapping (enabled = false when off)
};

MissionSummary summarize(const Mission& mission, const std::string& world_name, double wall_time);

/// run.json text.
std::string to_json(const MissionSummary& summary);

/// Writes map.pgm, map.yaml, map.png, coverage.png, trajectory.txt (estimate, timestamps in
/// simulated seconds) and run.json into `dir`.
void write_mission_outputs(const Mission& mission, const MissionSummary& summary, const std::string& dir);

}  // namespace lookahead::exploration
