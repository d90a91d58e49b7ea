// SPDX-License-Identifier: MIT
// `lookahead explore`: one exploration mission in the simulator, with its map, pictures,
// coverage curve, animation and run.json.
#include <spdlog/spdlog.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <optional>

#include "commands.hpp"
#include "lookahead/exploration/animation_writer.hpp"
#include "lookahead/exploration/mission.hpp"
#include "lookahead/exploration/mission_config.hpp"
#include "lookahead/exploration/mission_picture.hpp"
#include "lookahead/exploration/mission_report.hpp"
#include "lookahead/exploration/world_source.hpp"
#include "lookahead/planner/ompl_logging.hpp"
#include "process_stats.hpp"
#include "progress_bar.hpp"

namespace lookahead::app {
namespace {

struct ExploreArgs {
  exploration::WorldSpec world;
  // Unset options keep MissionOptions::defaults(): the one place defaults live.
  std::optional<std::string> strategy;
  std::string config;  ///< mission YAML (config/mission/default.yaml documents every key)
  std::string robot;   ///< robot YAML (config/robot/): robot, laser and odometry, over the config
  std::optional<std::string> pose;
  std::optional<std::uint64_t> seed;  ///< unset: the config's mission.seed (a study's run_config.yaml replays)
  std::string out = "out/explore";
  std::optional<int> particles;
  std::optional<double> time_limit;
  std::optional<double> coverage_goal;
  std::vector<double> start;
  bool animation = true;
  bool log = false;
  std::string log_format = "carmen";
  bool predict = false;
  double laser_range = 0.0;
  double laser_fov_deg = 0.0;
  std::optional<int> threads;  ///< unset: the config's slam.filter.threads
  double robot_radius = 0.0;
};

exploration::MissionOptions mission_options(const ExploreArgs& a) {
  exploration::MissionOptions o =
      a.config.empty() ? exploration::MissionOptions::defaults() : exploration::load_mission_options(a.config);
  // A robot file is a partial mission file: the keys it names override the config.
  if (!a.robot.empty()) o = exploration::load_mission_options(a.robot, o);
  if (a.strategy) o.strategy = *a.strategy;
  if (a.predict) o.slam.prediction.enabled = true;  // P-SLAM weights; implies predictions
  if (a.seed) o.seed = *a.seed;
  if (a.particles) o.slam.particles = *a.particles;
  if (a.time_limit) o.time_limit = *a.time_limit;
  if (a.coverage_goal) o.coverage_goal = *a.coverage_goal;
  if (a.laser_range > 0) o.laser.max_range = a.laser_range;
  if (a.laser_fov_deg > 0) o.laser.fov = a.laser_fov_deg * M_PI / 180.0;
  if (a.threads) o.slam.threads = *a.threads;
  if (a.robot_radius > 0) o.robot.radius = a.robot_radius;
  if (a.pose == std::string("truth"))
    o.pose_source = exploration::PoseSource::kTruth;
  else if (a.pose == std::string("slam"))
    o.pose_source = exploration::PoseSource::kSlam;
  else if (a.pose)
    throw std::invalid_argument("--pose must be slam or truth, not '" + *a.pose + "'");
  o.harmonize();
  return o;
}

int run_explore(ExploreArgs a) {
  planner::set_ompl_log_level(planner::OmplLogLevel::kWarn);
  const exploration::MissionOptions options = mission_options(a);
  a.world.seed = options.seed;
  if (a.start.size() == 3) a.world.start = slam::Pose2{a.start[0], a.start[1], a.start[2]};
  const exploration::GeneratedWorld world = exploration::load_world(a.world, options.robot.radius);
  spdlog::info("world {}: {:.1f} m x {:.1f} m, start ({:.2f}, {:.2f}); strategy {}, pose {}, seed {}", a.world.name,
               world.world.width_m(), world.world.height_m(), world.start.x, world.start.y, options.strategy,
               exploration::pose_source_name(options.pose_source), options.seed);
  std::filesystem::create_directories(a.out);
  exploration::Mission mission(world.world, world.start, options);
  if (a.log) mission.record_log(a.out + (a.log_format == "bag" ? "/run.bag" : "/run.log"));
  std::unique_ptr<exploration::AnimationWriter> video;
  if (a.animation) video = std::make_unique<exploration::AnimationWriter>(a.out + "/animation.mp4", 10.0);
  ProgressBar bar("explore", 100);
  double next_frame = 0.0;
  const auto start = std::chrono::steady_clock::now();
  mission.run([&](const exploration::Mission& m) {
    bar.update(static_cast<std::size_t>(m.coverage() * 100),
               fmt::format("t {:.0f}s coverage {:.1f}%", m.time(), 100 * m.coverage()));
    if (video && m.time() >= next_frame) {
      video->add(exploration::render_mission(m, fmt::format("{}  t = {:.0f} s", a.world.name, m.time())));
      next_frame = m.time() + options.frame_period;
    }
  });
  bar.finish();
  const double wall = seconds_since(start);
  if (video) video->close();
  const exploration::MissionSummary s = exploration::summarize(mission, a.world.name, wall);
  exploration::write_mission_outputs(mission, s, a.out);
  spdlog::info(
      "{}: {:.0f} s simulated, {:.1f} m driven, coverage {:.1f}%, {} collision(s); "
      "{:.1f} s wall ({:.0f}x real time); wrote {}/map.png",
      s.status, s.simulated_time, s.path_length, 100 * s.coverage, s.statistics.collisions, wall, s.real_time_factor,
      a.out);
  return mission.status() == exploration::MissionStatus::kCollision ? 3 : 0;
}

}  // namespace

Run add_explore_command(CLI::App& app) {
  auto a = std::make_shared<ExploreArgs>();
  app.add_option("--config", a->config, "mission options YAML (see config/mission/default.yaml)");
  app.add_option("--robot", a->robot,
                 "robot YAML: body, laser, odometry (config/robot/pioneer3dx.yaml, p2explore.yaml)");
  app.add_option("--world", a->world.name, "office | maze | corridor | map .yaml | Stage .world | image")
      ->capture_default_str();
  app.add_option("--resolution", a->world.image_resolution, "m/pixel of a plain image world (required for one)");
  app.add_option("--pixel-rule", a->world.pixel_rule, "stage | only_white (plain images)")->capture_default_str();
  app.add_option("--laser-range", a->laser_range, "sensor range [m] (default 8, a SICK LMS-200 in Stage)");
  app.add_option("--laser-fov", a->laser_fov_deg, "sensor field of view [deg] (default 180)");
  app.add_option("--robot-radius", a->robot_radius, "robot disc radius [m] (default 0.25, a Pioneer 3-DX)");
  app.add_option("--threads", a->threads, "RBPF worker threads, 0 = all cores (default: slam.filter.threads)");
  app.add_option("--start", a->start, "start pose x y theta (default: the world's)")->expected(3);
  app.add_option("--strategy", a->strategy,
                 "nearest | utility | advantage | rate | predictive-rate | predictive | predictive-utility | "
                 "predictive-advantage (predictive-rate: gain seen through P-SLAM's predicted walls; the "
                 "other predictive-*: P-SLAM, skip predicted frontiers)");
  app.add_flag("--predict", a->predict, "P-SLAM: predict at each target and use hypotheses in the particle weights");
  app.add_option("--pose", a->pose, "slam (RBPF in the loop) | truth (planner-only); default slam");
  app.add_option(
      "--seed", a->seed,
      "seed of the world, sensor, odometry, SLAM and planner (overrides the config's mission.seed; default 1)");
  app.add_option("--particles", a->particles, "RBPF particles (default 30)");
  app.add_option("--time-limit", a->time_limit, "simulated seconds (default 1800)");
  app.add_option("--coverage-goal", a->coverage_goal, "stop at this share of the reachable area (default 0.95)");
  app.add_option("--out", a->out, "output folder")->capture_default_str();
  app.add_flag("!--no-animation", a->animation, "skip animation.mp4");
  app.add_flag("--log", a->log, "also write the run as a log `lookahead slam` replays (run.log or run.bag)");
  app.add_option("--log-format", a->log_format, "carmen (run.log) or bag (ROS1 run.bag)")
      ->check(CLI::IsMember({"carmen", "bag"}))
      ->capture_default_str();
  return [a] { return run_explore(*a); };
}

}  // namespace lookahead::app
