// SPDX-License-Identifier: MIT
#include "lookahead/exploration/study.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
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
#include "lookahead/exploration/study_plan.hpp"
#include "lookahead/slam/io/parse_error.hpp"
#include "lookahead/slam/io/provenance.hpp"

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
MissionSummary summary_from_json(const nlohmann::json& j) {
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
  s.statistics.stuck_goals = j.at("planner").at("stuck_goals").get<int>();
  s.statistics.backtracks = j.at("backtracks").get<int>();
  s.wall_time = j.at("wall_time_s").get<double>();
  s.real_time_factor = j.at("real_time_factor").get<double>();
  return s;
}

void write_curve(const fs::path& path, const std::vector<CoverageSample>& curve) {
  std::ofstream out(path);
  out << "time_s,path_length_m,coverage\n";
  out.precision(17);
  for (const CoverageSample& c : curve) out << c.time << ',' << c.path_length << ',' << c.coverage << '\n';
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
    if (!(row >> c.time >> comma1 >> c.path_length >> comma2 >> c.coverage)) throw std::runtime_error("bad row");
    curve.push_back(c);
  }
  return curve;
}

// One mission, written to `dir` through `dir`.partial so that the folder only ever holds a
// complete run.
std::string study_run_json(const StudyRunResult& r) {
  nlohmann::json j;
  j["mission_id"] = r.mission_id;
  j["plan_free_area_m2"] = r.plan_free_area_m2;
  j["predicted_coverage"] = r.predicted_coverage;
  return j.dump(2) + "\n";
}

void read_study_run_json(const std::string& text, StudyRunResult& r) {
  const nlohmann::json j = nlohmann::json::parse(text);
  r.mission_id = j.at("mission_id").get<std::string>();
  r.plan_free_area_m2 = j.at("plan_free_area_m2").get<double>();
  r.predicted_coverage = j.at("predicted_coverage").get<double>();
}

void write_text(const fs::path& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
  out.close();
  if (!out) throw slam::ParseError(path.string(), 0, "", "", "cannot write");
}

// nullopt when `stop` was set while it ran: an interrupted study reports what finished
// before the interruption, so a run ending after it is not published.
std::optional<StudyRunResult> execute_run(const GeneratedWorld& world, const std::string& label,
                                          const MissionOptions& options, const std::string& config_text,
                                          const std::string& mission_id, const fs::path& dir,
                                          const std::atomic<bool>* stop) {
  Mission mission(world.world, world.start, options);
  const auto start = Clock::now();
  mission.run();
  const double wall = std::chrono::duration<double>(Clock::now() - start).count();
  StudyRunResult r;
  r.finished = true;
  r.summary = summarize(mission, label, wall);
  r.curve = mission.coverage_curve();
  r.mission_id = mission_id;
  r.plan_free_area_m2 = world.world.free_area_m2();
  if (r.summary.prediction.enabled) r.predicted_coverage = r.summary.prediction.coverage_with_predictions;
  // Unique per process: a resubmitted array task may meet a folder its killed predecessor
  // left half-written.
  fs::path staging = dir;
  staging += fmt::format(".{}.partial", ::getpid());
  fs::remove_all(staging);
  write_mission_outputs(mission, r.summary, staging.string());
  write_curve(staging / "coverage.csv", r.curve);
  write_text(staging / "study_run.json", study_run_json(r));
  std::ofstream config(staging / "run_config.yaml");
  config << config_text;
  config.close();
  if (!config) throw slam::ParseError((staging / "run_config.yaml").string(), 0, "", "", "cannot write");
  if (stop && stop->load()) {
    fs::remove_all(staging);
    return std::nullopt;
  }
  fs::remove_all(dir);
  fs::rename(staging, dir);
  return r;
}

// The worlds the `needed` runs use; the others stay empty.
std::vector<std::optional<GeneratedWorld>> load_worlds(const StudySpec& spec, const std::vector<StudyRun>& runs,
                                                       const std::vector<std::size_t>& needed) {
  std::vector<std::optional<GeneratedWorld>> worlds(spec.worlds.size());
  for (const std::size_t i : needed) {
    const StudyWorld& w = spec.worlds[runs[i].world];
    if (worlds[runs[i].world]) continue;
    try {
      worlds[runs[i].world] = load_world(w.spec, spec.mission.robot.radius);
    } catch (const std::invalid_argument& e) {
      throw slam::ParseError(spec.source, w.line, "worlds.name", w.spec.name, e.what());
    }
  }
  return worlds;
}

std::string run_dir(const StudySpec& spec, const PlannedMission& m) { return spec.out + "/runs/" + m.folder; }

// Finished runs read back into `result`; returns the indices among `candidates` to run.
std::vector<std::size_t> read_back(const StudySpec& spec, const std::vector<PlannedMission>& plan,
                                   const std::vector<std::size_t>& candidates, StudyResult& result) {
  result.runs.resize(plan.size());
  std::vector<std::size_t> pending;
  std::vector<bool> candidate(plan.size(), false);
  for (const std::size_t i : candidates) candidate[i] = true;
  for (std::size_t i = 0; i < plan.size(); ++i) {
    auto done = read_finished_run(run_dir(spec, plan[i]), run_config_text(spec, plan[i].run, plan[i].id));
    if (done) {
      result.runs[i] = std::move(*done);
      ++result.reused;
    } else if (candidate[i]) {
      pending.push_back(i);
    }
  }
  return pending;
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

std::string run_config_text(const StudySpec& spec, const StudyRun& run, const std::string& mission_id) {
  std::string id = mission_id;
  if (id.empty()) {
    for (const PlannedMission& m : plan_missions(spec)) {
      if (m.run.world == run.world && m.run.strategy == run.strategy && m.run.seed == run.seed) id = m.id;
    }
  }
  const WorldSpec& w = spec.worlds.at(run.world).spec;
  std::string text = fmt::format("# mission id: {}\n# world: {}, resolution {}, pixel rule {}, seed {}", id, w.name,
                                 w.image_resolution, w.pixel_rule, w.seed);
  if (w.start) text += fmt::format(", start [{}, {}, {}]", w.start->x, w.start->y, w.start->theta);
  return text + "\n" + dump_mission_options(run_options(spec, run));
}

std::optional<StudyRunResult> read_finished_run(const std::string& dir, const std::string& config_text) {
  const fs::path d(dir);
  if (!fs::exists(d / "run.json") || read_text(d / "run_config.yaml") != config_text) return std::nullopt;
  try {
    // A run made by another build of lookahead is run again: the same options may decide
    // differently in other code, and a study must not mix the two.
    const nlohmann::json json = nlohmann::json::parse(read_text(d / "run.json"));
    if (json.at("provenance").at("commit") != slam::provenance(1).commit) return std::nullopt;
    StudyRunResult r;
    r.finished = true;
    r.reused = true;
    r.summary = summary_from_json(json);
    r.curve = read_curve(d / "coverage.csv");
    read_study_run_json(read_text(d / "study_run.json"), r);
    return r;
  } catch (const std::exception&) {
    return std::nullopt;  // half-written or damaged: run it again
  }
}

std::size_t StudyResult::finished() const {
  std::size_t n = 0;
  for (const StudyRunResult& r : runs) n += r.finished ? 1 : 0;
  return n;
}

StudyResult collect_study(const StudySpec& spec) {
  StudyResult result;
  read_back(spec, plan_missions(spec), {}, result);
  return result;
}

StudyResult run_study(const StudySpec& spec, const StudyProgressCallback& progress, unsigned workers) {
  StudyRunOptions options;
  options.workers = workers;
  return run_study(spec, progress, options);
}

StudyResult run_study(const StudySpec& spec, const StudyProgressCallback& progress, const StudyRunOptions& options) {
  const std::vector<PlannedMission> plan = plan_missions(spec);
  std::vector<std::size_t> candidates = options.only.value_or(std::vector<std::size_t>{});
  if (!options.only) {
    for (std::size_t i = 0; i < plan.size(); ++i) candidates.push_back(i);
  }
  StudyResult result;
  const std::vector<std::size_t> pending = read_back(spec, plan, candidates, result);
  std::vector<StudyRun> runs;
  for (const PlannedMission& m : plan) runs.push_back(m.run);
  const std::vector<std::optional<GeneratedWorld>> worlds = load_worlds(spec, runs, pending);
  fs::create_directories(spec.out + "/runs");

  StudyProgress state{0, pending.size(), result.reused, 0.0, "", {}};
  if (progress) progress(state);
  std::mutex mutex;  // guards state, result and error
  std::exception_ptr error;
  std::atomic<std::size_t> next{0};
  const auto start = Clock::now();
  const auto stopped = [&] { return options.stop && options.stop->load(); };
  const auto work = [&] {
    for (std::size_t k = next++; k < pending.size() && !stopped(); k = next++) {
      const PlannedMission& m = plan[pending[k]];
      {
        const std::lock_guard<std::mutex> lock(mutex);
        state.in_flight.push_back(m.folder);
      }
      try {
        std::optional<StudyRunResult> r =
            execute_run(*worlds[m.run.world], spec.worlds[m.run.world].label, run_options(spec, m.run),
                        run_config_text(spec, m.run, m.id), m.id, run_dir(spec, m), options.stop);
        const std::lock_guard<std::mutex> lock(mutex);
        if (!r) break;
        result.runs[pending[k]] = std::move(*r);
        ++state.done;
        ++result.executed;
        state.elapsed = std::chrono::duration<double>(Clock::now() - start).count();
        state.last_run = m.folder;
        state.in_flight.erase(std::find(state.in_flight.begin(), state.in_flight.end(), m.folder));
        if (progress) progress(state);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(mutex);
        if (!error) error = std::current_exception();
        next = pending.size();  // no new runs; those in flight finish and are kept
      }
    }
  };
  const unsigned hw = options.workers ? options.workers : std::max(1u, std::thread::hardware_concurrency());
  std::vector<std::thread> pool;
  for (unsigned t = 0; t < std::min<std::size_t>(hw, pending.size()); ++t) pool.emplace_back(work);
  for (std::thread& t : pool) t.join();
  if (error) std::rethrow_exception(error);
  return result;
}

}  // namespace lookahead::exploration
