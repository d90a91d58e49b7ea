// SPDX-License-Identifier: MIT
// An exploration-time study (`lookahead study STUDY.yaml`): every world x strategy x seed of
// a StudySpec as one mission, on all cores or one shard of a cluster job, resumable. Run r
// writes OUT/runs/<r>/ (map, pictures, trajectory, run.json via write_mission_outputs, plus
// coverage.csv, study_run.json with its mission id and the plan's free area, and
// run_config.yaml, its mission id, the world and options it ran with). The folder is filled under
// <r>.partial and renamed when the run is complete, so run.json appears atomically: a run is
// finished iff its run.json parses and its run_config.yaml says what this study would run
// now. An interrupted study therefore resumes where it stopped, and a changed world or
// option redoes exactly the runs it affects.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "lookahead/exploration/mission_metrics.hpp"
#include "lookahead/exploration/mission_report.hpp"
#include "lookahead/exploration/study_config.hpp"

namespace lookahead::exploration {

struct StudyRun {
  std::size_t world = 0;  ///< index into StudySpec::worlds
  std::string strategy;
  std::uint64_t seed = 0;
};

struct StudyRunResult {
  bool finished = false;  ///< false: not run yet (a merge of a partial study)
  MissionSummary summary;
  std::vector<CoverageSample> curve;
  bool reused = false;             ///< read back from a previous invocation, not run now
  std::string mission_id;          ///< study_plan.hpp
  double plan_free_area_m2 = 0.0;  ///< every free cell of the world, reachable or not
  /// Coverage counting confirmed predictions (P-SLAM look-ahead); < 0 when prediction is off.
  double predicted_coverage = -1.0;
};

/// What a progress callback sees: `done` of `total` runs to execute now (finished runs of
/// an earlier invocation are counted in `reused`, not in `total`).
struct StudyProgress {
  std::size_t done = 0, total = 0, reused = 0;
  double elapsed = 0.0;                ///< wall clock since the runs started [s]
  std::string last_run;                ///< id of the run that just finished
  std::vector<std::string> in_flight;  ///< ids of the runs executing now
};
/// Called once before the first run and after every run, one call at a time, possibly from
/// a worker thread.
using StudyProgressCallback = std::function<void(const StudyProgress&)>;

struct StudyResult {
  std::vector<StudyRunResult> runs;  ///< in plan_runs() order; unfinished ones not run here
  std::size_t executed = 0, reused = 0;
  [[nodiscard]] std::size_t finished() const;
};

struct StudyRunOptions {
  unsigned workers = 0;  ///< 0 = std::thread::hardware_concurrency()
  /// Plan indices to run (a shard); nullopt = all. The others are read back when finished.
  std::optional<std::vector<std::size_t>> only;
  /// Set (e.g. by a signal) to start no new run; those in flight finish and are kept.
  const std::atomic<bool>* stop = nullptr;
};

/// World-major, then strategy, then seed, as the study lists them.
std::vector<StudyRun> plan_runs(const StudySpec& spec);
/// "<world label>__<strategy>__<seed>"
std::string run_id(const StudySpec& spec, const StudyRun& run);
/// The options one run uses: the study's, with its strategy and seed, one SLAM thread.
MissionOptions run_options(const StudySpec& spec, const StudyRun& run);
/// What run_config.yaml holds: the mission id, the world as the study gives it, then every
/// mission option. Without `mission_id` the id is computed (study_plan.hpp).
std::string run_config_text(const StudySpec& spec, const StudyRun& run, const std::string& mission_id = "");
/// The finished run in `dir` when its run_config.yaml equals `config_text`; nullopt means
/// "run it" (missing, half-written, damaged or made with other inputs).
std::optional<StudyRunResult> read_finished_run(const std::string& dir, const std::string& config_text);
/// Every finished run of the plan read back from OUT/runs, without running anything.
StudyResult collect_study(const StudySpec& spec);

/// Runs what is not finished on `workers` threads (0 = std::thread::hardware_concurrency()),
/// each mission single-threaded. A run that throws stops the study after the runs in flight
/// (their folders are complete) and the exception is rethrown.
StudyResult run_study(const StudySpec& spec, const StudyProgressCallback& progress = nullptr, unsigned workers = 0);
StudyResult run_study(const StudySpec& spec, const StudyProgressCallback& progress, const StudyRunOptions& options);

}  // namespace lookahead::exploration
