// SPDX-License-Identifier: MIT
// plan, run, merge and the local study (study_verbs.hpp).
#include "study_verbs.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <filesystem>
#include <memory>
#include <thread>

#include "lookahead/exploration/mission_config.hpp"
#include "lookahead/exploration/study_plan.hpp"
#include "lookahead/exploration/study_report.hpp"
#include "lookahead/exploration/study_shard.hpp"
#include "lookahead/exploration/study_tables.hpp"
#include "lookahead/planner/ompl_logging.hpp"
#include "lookahead/slam/io/parse_error.hpp"
#include "progress_bar.hpp"
#include "study_interrupt.hpp"
#include "study_progress_log.hpp"

namespace lookahead::app {
namespace {

namespace ex = exploration;

ex::StudySpec load(const StudyArgs& a) {
  planner::set_ompl_log_level(planner::OmplLogLevel::kWarn);
  ex::StudySpec spec = ex::load_study(a.file);
  if (!a.out.empty()) spec.out = a.out;
  return spec;
}

std::string host_name() {
  char name[256] = {};
  ::gethostname(name, sizeof(name) - 1);
  return name;
}

// The plan, with the host in the error when a world file is missing: on a cluster the node
// that ran the task is the one without the data.
std::vector<ex::PlannedMission> plan_here(const ex::StudySpec& spec) {
  try {
    return ex::plan_missions(spec);
  } catch (const slam::ParseError& e) {
    spdlog::error("on host {}:", host_name());
    throw;
  }
}

std::optional<ex::Shard> requested_shard(const StudyArgs& a) {
  try {
    if (!a.shard.empty()) return ex::parse_shard(a.shard);
    return ex::shard_from_slurm_environment();
  } catch (const std::invalid_argument& e) {
    throw slam::ParseError("command line", 0, "--shard", a.shard, e.what());
  }
}

void write_outputs(const ex::StudySpec& spec, const ex::StudyResult& result) {
  ex::write_study_outputs(spec, result);
  spdlog::info("{}", ex::overall_line(spec, result));
  spdlog::info("wrote {0}/results.csv, {0}/summary.md, {0}/report.html and plots", spec.out);
}

// Runs `only` (all when nullopt) with a bar on a terminal and the progress log.
ex::StudyResult run_missions(const ex::StudySpec& spec, const StudyArgs& a,
                             const std::optional<std::vector<std::size_t>>& only, const std::string& log_name,
                             const std::string& what, const std::atomic<bool>* stop) {
  const unsigned jobs = a.jobs ? a.jobs : std::max(1u, std::thread::hardware_concurrency());
  StudyProgressLog log(spec.out + "/logs/" + log_name, what);
  spdlog::info(
      "{}: {} world(s) x {} strateg{} x {} seed(s), pose {}, time limit {:g} s; {}; {} "
      "worker(s); progress in {}",
      spec.name, spec.worlds.size(), spec.strategies.size(), spec.strategies.size() == 1 ? "y" : "ies",
      spec.seeds.size(), ex::pose_source_name(spec.mission.pose_source), spec.mission.time_limit, what, jobs,
      log.path());
  std::unique_ptr<ProgressBar> bar;  // made at the first report, which knows how many runs remain
  ex::StudyRunOptions options;
  options.workers = jobs;
  options.only = only;
  options.stop = stop;
  const ex::StudyResult result = ex::run_study(
      spec,
      [&](const ex::StudyProgress& p) {
        log.update(p);
        if (!bar) {
          if (p.reused > 0) spdlog::info("{} run(s) finished earlier are reused", p.reused);
          if (p.total == 0) return;  // nothing left to run: no bar
          bar = std::make_unique<ProgressBar>("study", p.total);
        }
        bar->update(p.done, p.last_run);
      },
      options);
  if (bar) bar->finish();
  spdlog::info("{} run(s) executed", result.executed);
  return result;
}

// Staging folders of missions an earlier, interrupted invocation left (runs/<run>.<pid>.partial).
void remove_staging_folders(const ex::StudySpec& spec) {
  const std::filesystem::path runs = spec.out + "/runs";
  if (!std::filesystem::exists(runs)) return;
  for (const auto& e : std::filesystem::directory_iterator(runs)) {
    if (e.path().extension() == ".partial") std::filesystem::remove_all(e.path());
  }
}

}  // namespace

int study_plan(const StudyArgs& a) {
  const ex::StudySpec spec = load(a);
  const std::vector<ex::PlannedMission> plan = plan_here(spec);
  ex::write_plan(spec, plan);
  std::size_t finished = 0;
  for (const ex::StudyRunResult& r : ex::collect_study(spec).runs) finished += r.finished ? 1 : 0;
  spdlog::info("{} mission(s), {} already finished; plan in {}", plan.size(), finished, ex::plan_path(spec));
  return 0;
}

int study_run(const StudyArgs& a) {
  const ex::StudySpec spec = load(a);
  const std::optional<ex::Shard> shard = requested_shard(a);
  const std::vector<ex::PlannedMission> plan = plan_here(spec);
  if (std::filesystem::exists(ex::plan_path(spec)))
    ex::check_plan(spec, plan);  // a study edited since `study plan` runs nothing stale
  else
    ex::write_plan(spec, plan);
  if (!shard) {
    run_missions(spec, a, std::nullopt, "progress.log", "every mission", nullptr);
    return 0;
  }
  const auto only = ex::shard_missions(plan.size(), *shard);
  const std::string what =
      fmt::format("shard {}/{} ({} mission(s)) on {}", shard->index, shard->count, only.size(), host_name());
  run_missions(spec, a, only, fmt::format("progress_{}_of_{}.log", shard->index, shard->count), what, nullptr);
  return 0;
}

int study_merge(const StudyArgs& a) {
  const ex::StudySpec spec = load(a);
  const std::vector<ex::PlannedMission> plan = plan_here(spec);
  if (!std::filesystem::exists(ex::plan_path(spec))) ex::write_plan(spec, plan);
  const ex::StudyResult result = ex::collect_study(spec);
  write_outputs(spec, result);
  const std::size_t missing = result.runs.size() - result.finished();
  if (missing > 0)
    spdlog::warn(
        "{} of {} mission(s) are not finished (listed in {}/missing.txt); run the "
        "study (or resubmit the array) to complete them",
        missing, result.runs.size(), spec.out);
  return 0;
}

int study_local(const StudyArgs& a) {
  const ex::StudySpec spec = load(a);
  remove_staging_folders(spec);  // the local study owns its folder: nothing else runs there
  ex::write_plan(spec, plan_here(spec));
  std::atomic<bool> stop{false};
  const StudyInterrupt interrupt([&](int sig) {
    stop = true;
    spdlog::warn("signal {}: writing the results of the finished runs", sig);
    write_outputs(spec, ex::collect_study(spec));
  });
  const ex::StudyResult result = run_missions(spec, a, std::nullopt, "progress.log", "every mission", &stop);
  write_outputs(spec, result);
  return 0;
}

}  // namespace lookahead::app
