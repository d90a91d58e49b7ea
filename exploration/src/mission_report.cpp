// SPDX-License-Identifier: MIT
#include "lookahead/exploration/mission_report.hpp"

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "lookahead/exploration/hypothesis_pictures.hpp"
#include "lookahead/exploration/line_plot.hpp"
#include "lookahead/exploration/mission_config.hpp"
#include "lookahead/exploration/mission_picture.hpp"
#include "lookahead/slam/io/map_io.hpp"
#include "lookahead/slam/io/parse_error.hpp"
#include "lookahead/slam/io/run_json.hpp"
#include "lookahead/slam/io/trajectory_io.hpp"

namespace lookahead::exploration {

MissionSummary summarize(const Mission& m, const std::string& world_name, double wall_time) {
  MissionSummary s;
  s.world = world_name;
  s.strategy = m.options().strategy;
  s.pose_source = m.options().pose_source == PoseSource::kSlam ? "slam" : "truth";
  s.status = to_string(m.status());
  s.seed = m.options().seed;
  s.particles = m.slam() ? m.options().slam.particles : 0;
  s.simulated_time = m.time();
  s.path_length = m.path_length();
  s.coverage = m.coverage();
  s.milestones = coverage_milestones(m.coverage_curve());
  s.reachable_area_m2 = m.reachable().area_m2;
  s.quality = map_quality(m.map(), m.world(), m.reachable());
  const auto& t = m.true_path();
  const auto& e = m.estimated_path();
  for (std::size_t i = 0; i < std::min(t.size(), e.size()); ++i) {
    s.slam_position_error_mean += std::hypot(t[i].x - e[i].x, t[i].y - e[i].y) / static_cast<double>(t.size());
  }
  s.slam_position_error_final = std::hypot(m.truth().x - m.estimate().x, m.truth().y - m.estimate().y);
  s.statistics = m.statistics();
  s.wall_time = wall_time;
  s.real_time_factor = wall_time > 0 ? m.time() / wall_time : 0.0;
  s.prediction = summarize_predictions(m);
  return s;
}

namespace {

// A time that may never have come (< 0): null in the JSON.
nlohmann::json optional_time(double t) { return t >= 0 ? nlohmann::json(t) : nlohmann::json(nullptr); }

// Each hypothesis with where it came from and how the world scored it (for diagnosis).
nlohmann::json hypotheses_json(const std::vector<PredictionRecord>& records) {
  nlohmann::json out = nlohmann::json::array();
  for (const PredictionRecord& r : records) {
    nlohmann::json j{{"time_s", r.time},
                     {"target", {r.x, r.y}},
                     {"psi", r.psi},
                     {"area_m2", r.area},
                     {"diameter_m", r.diameter},
                     {"psi_world", r.truth.psi},
                     {"psi_solid_world", r.truth.psi_solid_world},
                     {"cells", r.truth.cells},
                     {"cells_right", r.truth.correct},
                     {"wall_cells", r.truth.wall_cells},
                     {"wall_cells_right", r.truth.walls_correct},
                     {"predicted_wall_samples", r.truth.predicted_walls},
                     {"world_wall_samples", r.truth.world_walls}};
    if (r.alignment) {
      j["control_point"] = {r.alignment->control.x, r.alignment->control.y};
      j["reference_point"] = {r.alignment->reference.x, r.alignment->reference.y};
      j["theta"] = r.alignment->reference_to_target.theta;
    }
    out.push_back(j);
  }
  return out;
}

nlohmann::json prediction_json(const PredictionSummary& p) {
  return {{"hypothesis_list", hypotheses_json(p.hypothesis_records)},
          {"requests", p.requests},
          {"hypotheses", p.hypotheses},
          {"no_control_point", p.no_control_point},
          {"no_match", p.no_match},
          {"psi_world", p.psi_world},
          {"psi_solid_world", p.psi_solid_world},
          {"mean_psi_world", p.mean_psi_world},
          {"share_psi_world_above_0_4", p.share_psi_world_above_04},
          {"predicted_area_m2", p.predicted_area},
          {"cell_accuracy", p.cell_accuracy},
          {"in_use",
           {{"cells", p.in_use.cells},
            {"cells_right", p.in_use.correct},
            {"wall_cells", p.in_use.wall_cells},
            {"wall_cells_right", p.in_use.walls_correct}}},
          {"mean_prediction_s", p.mean_seconds},
          {"max_prediction_s", p.max_seconds},
          {"final_predicted_area_m2", p.final_predicted_area},
          {"final_predicted_accuracy", p.final_predicted_accuracy},
          {"final_predicted_area_inside_m2", p.final_predicted_area_inside},
          {"final_predicted_accuracy_inside", p.final_predicted_accuracy_inside},
          {"coverage_with_predictions", p.coverage_with_predictions},
          {"rest_predicted_s", optional_time(p.rest_predicted_time)},
          {"time_to_goal_with_predictions_s", optional_time(p.time_to_goal_with_predictions)},
          {"skip_protocol_end_s", optional_time(p.skip_protocol_end)},
          {"coverage_with_predictions_at_skip_end", p.coverage_with_predictions_at_skip_end},
          {"path_at_skip_end_m", p.path_at_skip_end},
          {"filter",
           {{"hypotheses", p.filter_hypotheses},
            {"predicted_updates", p.filter_predicted_updates},
            {"used", p.filter_used},
            {"rejected_by_hit_ratio", p.filter_rejected}}}};
}

}  // namespace

std::string to_json(const MissionSummary& s) {
  nlohmann::json j;
  j["world"] = s.world;
  j["strategy"] = s.strategy;
  j["pose_source"] = s.pose_source;
  j["status"] = s.status;
  j["seed"] = s.seed;
  j["particles"] = s.particles;
  j["simulated_time_s"] = s.simulated_time;
  j["path_length_m"] = s.path_length;
  j["coverage"] = s.coverage;
  j["reachable_free_area_m2"] = s.reachable_area_m2;
  for (const Milestone& ms : s.milestones) {
    const std::string k = std::to_string(static_cast<int>(std::lround(ms.level * 100)));
    j["time_to_" + k + "_s"] = ms.reached ? nlohmann::json(ms.time) : nlohmann::json(nullptr);
    j["path_to_" + k + "_m"] = ms.reached ? nlohmann::json(ms.path_length) : nlohmann::json(nullptr);
  }
  j["map_precision"] = s.quality.precision;
  j["map_recall"] = s.quality.recall;
  j["collisions"] = s.statistics.collisions;
  j["planner"] = {{"selections", s.statistics.selections},         {"plans", s.statistics.plans},
                  {"failures", s.statistics.plan_failures},        {"replans", s.statistics.replans},
                  {"stuck_goals", s.statistics.stuck_goals},       {"forgiven_goals", s.statistics.forgiven_goals},
                  {"grid_fallbacks", s.statistics.grid_fallbacks}, {"planning_time_s", s.statistics.planning_time}};
  j["safety_stops"] = s.statistics.safety_stops;
  j["stop_escapes"] = s.statistics.stop_escapes;
  j["backtracks"] = s.statistics.backtracks;
  j["squeezes"] = s.statistics.squeezes;
  j["kept_paths"] = s.statistics.kept_paths;
  j["retired_frontier_cells"] = s.statistics.retired_frontier_cells;
  j["slam_position_error_mean_m"] = s.slam_position_error_mean;
  j["slam_position_error_final_m"] = s.slam_position_error_final;
  j["scans"] = s.statistics.scans;
  j["wall_time_s"] = s.wall_time;
  j["real_time_factor"] = s.real_time_factor;
  if (s.prediction.enabled) j["prediction"] = prediction_json(s.prediction);
  return j.dump(2) + "\n";
}

void write_mission_outputs(const Mission& m, const MissionSummary& s, const std::string& dir) {
  std::filesystem::create_directories(dir);
  slam::write_map(slam::to_probability_map(m.map()), dir, "map");
  const slam::BgrImage img = render_mission(m, s.world + " | " + s.strategy + " | " + s.status);
  const cv::Mat mat(img.height, img.width, CV_8UC3, const_cast<std::uint8_t*>(img.pixels.data()));
  if (!cv::imwrite(dir + "/map.png", mat)) throw slam::ParseError(dir + "/map.png", 0, "", "", "cannot write image");
  PlotSeries series{"coverage", {}, {}, series_colour(0)};
  for (const CoverageSample& c : m.coverage_curve()) {
    series.x.push_back(c.time);
    series.y.push_back(c.coverage);
  }
  write_line_plot(dir + "/coverage.png", {series},
                  {"coverage of the reachable free area", "simulated time [s]", "coverage", 800, 450, 0.0, 1.0});
  std::vector<slam::StampedPose> traj;
  const double dt = m.options().laser.period() * 5;  // one pose kept every 5 scans
  for (std::size_t i = 0; i < m.estimated_path().size(); ++i)
    traj.push_back({m.options().laser.period() + dt * static_cast<double>(i), m.estimated_path()[i]});
  slam::write_trajectory(dir + "/trajectory.txt", traj);
  // The figures, then where they come from and the whole effective configuration.
  slam::write_run_json(dir, nlohmann::json::parse(to_json(s)), m.options().slam.threads,
                       dump_mission_options(m.options()));
  if (m.lookahead() && m.lookahead()->options().pictures)
    write_hypothesis_pictures(*m.lookahead(), m.world(), dir + "/predictions");
}

}  // namespace lookahead::exploration
