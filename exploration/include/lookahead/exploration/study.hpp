// SPDX-License-Identifier: MIT
// An exploration-time study (`lookahead study STUDY.yaml`): every world x strategy x seed of
// a StudySpec as one mission, on all cores, resumable. Run r writes OUT/runs/<r>/ (map,
// pictures, trajectory, run.json via write_mission_outputs, plus coverage.csv and
// run_config.yaml, the world and options it ran with). The folder is filled under
// <r>.partial and renamed when the run is complete, so run.json appears atomically: a run is
// finished iff its run.json parses and its run_config.yaml says what this study would run
// now. An interrupted study therefore resumes where it stopped, and a changed world or
// option redoes exactly the runs it affects.
#pragma once

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
  MissionSummary summary;
  std::vector<CoverageSample> curve;
  bool reused = false;  ///< read back from a previous invocation, not run now
};

/// What a progress callback sees: `done` of `total` runs to execute now (finished runs of
/// an earlier invocation are counted in `reused`, not in `total`).
struct StudyProgress {
  std::size_t done = 0, total = 0, reused = 0;
  double elapsed = 0.0;  ///< wall clock since the runs started [s]
  std::string last_run;  ///< id of the run that just finished
};
/// Called once before the first run and after every run, one call at a time, possibly from
/// a worker thread.
using StudyProgressCallback = std::function<void(const StudyProgress&)>;

struct StudyResult {
  std::vector<StudyRunResult> runs;  ///< in plan_runs() order
  std::size_t executed = 0, reused = 0;
};

/// World-major, then strategy, then seed, as the study lists them.
std::vector<StudyRun> plan_runs(const StudySpec& spec);
/// "<world label>__<strategy>__<seed>"
std::string run_id(const StudySpec& spec, const StudyRun& run);
/// The options one run uses: the study's, with its strategy and seed, one SLAM thread.
MissionOptions run_options(const StudySpec& spec, const StudyRun& run);
/// What run_config.yaml holds: the world as the study gives it, then every mission option.
std::string run_config_text(const StudySpec& spec, const StudyRun& run);
/// The finished run in `dir` when its run_config.yaml equals `config_text`; nullopt means
/// "run it" (missing, half-written, damaged or made with other inputs).
std::optional<StudyRunResult> read_finished_run(const std::string& dir,
                                                const std::string& config_text);

/// Runs what is not finished on `workers` threads (0 = std::thread::hardware_concurrency()),
/// each mission single-threaded. A run that throws stops the study after the runs in flight
/// (their folders are complete) and the exception is rethrown.
StudyResult run_study(const StudySpec& spec, const StudyProgressCallback& progress = nullptr,
                      unsigned workers = 0);

}  // namespace lookahead::exploration
