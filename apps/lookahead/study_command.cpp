// SPDX-License-Identifier: MIT
// `lookahead study STUDY.yaml`: worlds x strategies x seeds of exploration missions on all
// cores, resumable, with results.csv, summary.md (means, Welch's t-tests) and plots.
#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <memory>
#include <thread>

#include "commands.hpp"
#include "lookahead/exploration/mission_config.hpp"
#include "lookahead/exploration/study.hpp"
#include "lookahead/exploration/study_report.hpp"
#include "lookahead/planner/ompl_logging.hpp"
#include "progress_bar.hpp"

namespace lookahead::app {
namespace {

struct StudyArgs {
  std::string file;
  std::string out;    // overrides the study's out
  unsigned jobs = 0;  // 0 = every core
};

int run_study_command(const StudyArgs& a) {
  planner::set_ompl_log_level(planner::OmplLogLevel::kWarn);
  exploration::StudySpec spec = exploration::load_study(a.file);
  if (!a.out.empty()) spec.out = a.out;
  const unsigned jobs = a.jobs ? a.jobs : std::max(1u, std::thread::hardware_concurrency());
  spdlog::info(
      "study {}: {} world(s) x {} strateg{} x {} seed(s), pose {}, time limit {:g} s; {} "
      "worker(s); out {}",
      spec.name, spec.worlds.size(), spec.strategies.size(),
      spec.strategies.size() == 1 ? "y" : "ies", spec.seeds.size(),
      exploration::pose_source_name(spec.mission.pose_source), spec.mission.time_limit, jobs,
      spec.out);
  std::unique_ptr<ProgressBar> bar;  // made at the first report, which knows how many runs remain
  const exploration::StudyResult result = exploration::run_study(
      spec,
      [&](const exploration::StudyProgress& p) {
        if (!bar) {
          if (p.reused > 0) spdlog::info("{} run(s) finished earlier are reused", p.reused);
          if (p.total == 0) return;  // nothing left to run: no bar
          bar = std::make_unique<ProgressBar>("study", p.total);
        }
        bar->update(p.done, p.last_run);
      },
      jobs);
  if (bar) bar->finish();
  exploration::write_study_outputs(spec, result);
  spdlog::info("{} run(s) executed, {} reused; wrote {}/results.csv, {}/summary.md and plots",
               result.executed, result.reused, spec.out, spec.out);
  return 0;
}

}  // namespace

Run add_study_command(CLI::App& app) {
  auto a = std::make_shared<StudyArgs>();
  app.add_option("study", a->file, "study YAML (worlds, strategies, seeds; see config/study/)")
      ->required();
  app.add_option("--out", a->out, "output folder (default: the study's out, or out/study/<name>)");
  app.add_option("--jobs", a->jobs, "runs in parallel (default: every core)");
  return [a] { return run_study_command(*a); };
}

}  // namespace lookahead::app
