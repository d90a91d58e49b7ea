// SPDX-License-Identifier: MIT
// What a study writes into its output folder from the runs that are finished:
//   results.csv          one row per finished run (world, strategy, seed, status, times, path
//                        lengths, coverage, map precision/recall, collisions, reachable area
//                        and its share of the plan, stuck goals, backtracks, coverage with
//                        predictions, mission id, wall time, speed-up);
//   overall.csv          per strategy and for all: missions, count of each end status
//                        (coverage_reached = reached the goal), and the missions not finished;
//   missing.txt          the runs of the plan that are not finished, one per line;
//   summary.md           the overall line and status table, then per world and strategy:
//                        runs, mean +- std of time and path length to 95 % coverage, share
//                        reaching it, collisions, reachable area, stuck goals, backtracks; per
//                        world, Welch's t-test and the paired comparison on the seed between
//                        every pair of strategies;
//   report.html          the same tables, the plots and every run's map as a linked thumbnail
//                        (study_html.hpp);
//   coverage_<world>.png mean coverage curve per strategy;
//   time_to_95.png       mean time to 95 % per world and strategy, std whiskers.
#pragma once

#include <string>
#include <vector>

#include "lookahead/exploration/study.hpp"

namespace lookahead::exploration {

/// The runs of one world and strategy, in seed order.
std::vector<const StudyRunResult*> runs_of(const StudySpec& spec, const StudyResult& result, std::size_t world,
                                           const std::string& strategy);

std::string study_results_csv(const StudySpec& spec, const StudyResult& result);
std::string study_overall_csv(const StudySpec& spec, const StudyResult& result);
std::string study_summary_markdown(const StudySpec& spec, const StudyResult& result);
/// Folder names (run_id) of the planned runs that are not finished.
std::vector<std::string> missing_runs(const StudySpec& spec, const StudyResult& result);
/// coverage_<world label>.png for every world and time_to_95.png, into `dir`.
void write_study_plots(const std::string& dir, const StudySpec& spec, const StudyResult& result);

/// Mean coverage of `curves` on `grid` (simulated seconds): each curve is interpolated
/// linearly and holds its last value after it ends (the mission stopped; its map stays).
std::vector<double> mean_coverage_curve(const std::vector<const std::vector<CoverageSample>*>& curves,
                                        const std::vector<double>& grid);

/// All of the above into spec.out.
void write_study_outputs(const StudySpec& spec, const StudyResult& result);

}  // namespace lookahead::exploration
