// SPDX-License-Identifier: MIT
#include "lookahead/exploration/study.hpp"

#include <fmt/format.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "lookahead/exploration/mission.hpp"
#include "lookahead/exploration/mission_config.hpp"
#include "lookahead/slam/io/parse_error.hpp"

namespace lookahead::exploration {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// run.json back into the figures the study tables need; throws on anything missing.
MissionSummary summary_from_json(const std::string& text) {
  const nlohmann::json j = nlohmann::json::parse(text);
  MissionSummary s;
  s.world = j.at("world").get<std::string>();
  s.strategy = j.at("strategy").get<std::string>();
  s.pose_source = j.at("pose_source").get<std::string>();
  s.status = j.at("status").get<std::string>();
  s.seed = j.at("seed").get<std::uint64_t>();
  s.particles = j.at("particles").get<int>();
  s.simulated_time = j.at("simulated_time_s").get<double>();
  s.path_length = j.at("path_length_m").get<double>();
  s.coverage = j.at("coverage").get<double>();
  s.reachable_area_m2 = j.at("reachable_free_area_m2").get<double>();
  const int levels[] = {90, 95, 99};
  for (std::size_t i = 0; i < s.milestones.size(); ++i) {
    Milestone& m = s.milestones[i];
    m.level = levels[i] / 100.0;
    const auto& t = j.at("time_to_" + std::to_string(levels[i]) + "_s");
    m.reached = !t.is_null();
    if (m.reached) {
      m.time = t.get<double>();
      m.path_length = j.at("path_to_" + std::to_string(levels[i]) + "_m").get<double>();
    }
  }
  s.quality.precision = j.at("map_precision").get<double>();
  s.quality.recall = j.at("map_recall").get<double>();
  s.statistics.collisions = j.at("collisions").get<int>();
  s.wall_time = j.at("wall_time_s").get<double>();
  s.real_time_factor = j.at("real_time_factor").get<double>();
  return s;
}

void write_curve(const fs::path& path, const std::vector<CoverageSample>& curve) {
  std::ofstream out(path);
  out << "time_s,path_length_m,coverage\n";
  out.precision(17);
  for (const CoverageSample& c : curve)
    out << c.time << ',' << c.path_length << ',' << c.coverage << '\n';
  if (!out) throw slam::ParseError(path.string(), 0, "", "", "cannot write");
}

std::vector<CoverageSample> read_curve(const fs::path& path) {
  std::ifstream in(path);
  std::string line;
  if (!std::getline(in, line)) throw std::runtime_error("no coverage.csv");
  std::vector<CoverageSample> curve;
  while (std::getline(in, line)) {
    CoverageSample c;
    char comma1 = 0, comma2 = 0;
    std::istringstream row(line);
    if (!(row >> c.time >> comma1 >> c.path_length >> comma2 >> c.coverage))
      throw std::runtime_error("bad row");
    curve.push_back(c);
  }
  return curve;
}

// One mission, written to `dir` through `dir`.partial so that the folder only ever holds a
// complete run.
StudyRunResult execute_run(const GeneratedWorld& world, const std::string& label,
                           const MissionOptions& options, const std::string& config_text,
                           const fs::path& dir) {
  Mission mission(world.world, world.start, options);
  const auto start = Clock::now();
  mission.run();
  const double wall = std::chrono::duration<double>(Clock::now() - start).count();
  StudyRunResult r{summarize(mission, label, wall), mission.coverage_curve(), false};
  fs::path staging = dir;
  staging += ".partial";
  fs::remove_all(staging);
  write_mission_outputs(mission, r.summary, staging.string());
  write_curve(staging / "coverage.csv", r.curve);
  std::ofstream config(staging / "run_config.yaml");
  config << config_text;
  config.close();
  if (!config)
    throw slam::ParseError((staging / "run_config.yaml").string(), 0, "", "", "cannot write");
  fs::remove_all(dir);
  fs::rename(staging, dir);
  return r;
}

std::vector<GeneratedWorld> load_worlds(const StudySpec& spec) {
  std::vector<GeneratedWorld> worlds;
  for (const StudyWorld& w : spec.worlds) {
    try {
      worlds.push_back(load_world(w.spec, spec.mission.robot.radius));
    } catch (const std::invalid_argument& e) {
      throw slam::ParseError(spec.source, w.line, "worlds.name", w.spec.name, e.what());
    }
  }
  return worlds;
}

}  // namespace

std::vector<StudyRun> plan_runs(const StudySpec& spec) {
  std::vector<StudyRun> runs;
  for (std::size_t w = 0; w < spec.worlds.size(); ++w)
    for (const std::string& strategy : spec.strategies)
      for (const std::uint64_t seed : spec.seeds) runs.push_back({w, strategy, seed});
  return runs;
}

std::string run_id(const StudySpec& spec, const StudyRun& run) {
  return spec.worlds.at(run.world).label + "__" + run.strategy + "__" + std::to_string(run.seed);
}

MissionOptions run_options(const StudySpec& spec, const StudyRun& run) {
  MissionOptions o = spec.mission;
  o.strategy = run.strategy;
  o.seed = run.seed;
  o.slam.threads = 1;  // the study is parallel over runs, not over particles
  o.frame_period = 0;  // no animation
  o.harmonize();
  return o;
}

std::string run_config_text(const StudySpec& spec, const StudyRun& run) {
  const WorldSpec& w = spec.worlds.at(run.world).spec;
  std::string text = fmt::format("# world: {}, resolution {}, pixel rule {}, seed {}", w.name,
                                 w.image_resolution, w.pixel_rule, w.seed);
  if (w.start) text += fmt::format(", start [{}, {}, {}]", w.start->x, w.start->y, w.start->theta);
  return text + "\n" + dump_mission_options(run_options(spec, run));
}

std::optional<StudyRunResult> read_finished_run(const std::string& dir,
                                                const std::string& config_text) {
  const fs::path d(dir);
  if (!fs::exists(d / "run.json") || read_text(d / "run_config.yaml") != config_text)
    return std::nullopt;
  try {
    return StudyRunResult{summary_from_json(read_text(d / "run.json")),
                          read_curve(d / "coverage.csv"), true};
  } catch (const std::exception&) {
    return std::nullopt;  // half-written or damaged: run it again
  }
}

StudyResult run_study(const StudySpec& spec, const StudyProgressCallback& progress,
                      unsigned workers) {
  const std::vector<GeneratedWorld> worlds = load_worlds(spec);
  const std::vector<StudyRun> runs = plan_runs(spec);
  StudyResult result;
  result.runs.resize(runs.size());
  std::vector<std::size_t> pending;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    auto done = read_finished_run(spec.out + "/runs/" + run_id(spec, runs[i]),
                                  run_config_text(spec, runs[i]));
    if (done)
      result.runs[i] = std::move(*done);
    else
      pending.push_back(i);
  }
  result.reused = runs.size() - pending.size();
  fs::create_directories(spec.out + "/runs");

  StudyProgress state{0, pending.size(), result.reused, 0.0, ""};
  if (progress) progress(state);
  std::mutex mutex;  // guards state, result and error
  std::exception_ptr error;
  std::atomic<std::size_t> next{0};
  const auto start = Clock::now();
  const auto work = [&] {
    for (std::size_t k = next++; k < pending.size(); k = next++) {
      const StudyRun& run = runs[pending[k]];
      try {
        StudyRunResult r =
            execute_run(worlds[run.world], spec.worlds[run.world].label, run_options(spec, run),
                        run_config_text(spec, run), spec.out + "/runs/" + run_id(spec, run));
        const std::lock_guard<std::mutex> lock(mutex);
        result.runs[pending[k]] = std::move(r);
        ++state.done;
        state.elapsed = std::chrono::duration<double>(Clock::now() - start).count();
        state.last_run = run_id(spec, run);
        if (progress) progress(state);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(mutex);
        if (!error) error = std::current_exception();
        next = pending.size();  // no new runs; those in flight finish and are kept
      }
    }
  };
  const unsigned hw = workers ? workers : std::max(1u, std::thread::hardware_concurrency());
  std::vector<std::thread> pool;
  for (unsigned t = 0; t < std::min<std::size_t>(hw, pending.size()); ++t) pool.emplace_back(work);
  for (std::thread& t : pool) t.join();
  if (error) std::rethrow_exception(error);
  result.executed = pending.size();
  return result;
}

}  // namespace lookahead::exploration
