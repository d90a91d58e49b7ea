// SPDX-License-Identifier: MIT
// The tables of a study, built once and rendered twice, into summary.md and report.html:
// the overall outcome per strategy (how many missions reached the coverage goal and how the
// others ended), per world the strategy table (times and paths to 95 %, the reachable area
// and its share of the plan, stuck goals, backtracks, predicted-versus-explored coverage),
// Welch's t-tests between strategies and the paired comparisons on the same seeds.
#pragma once

#include <string>
#include <vector>

#include "lookahead/exploration/study.hpp"

namespace lookahead::exploration {

struct StudyTable {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
};

/// "N of M missions reached the coverage goal (nearest 5/6, utility 6/6); K not finished."
std::string overall_line(const StudySpec& spec, const StudyResult& result);
/// Per strategy and in total: the count of each end status.
StudyTable status_table(const StudySpec& spec, const StudyResult& result);
StudyTable strategy_table(const StudySpec& spec, const StudyResult& result, std::size_t world);
/// Welch's t-test between every pair of strategies (empty with one strategy).
StudyTable welch_table(const StudySpec& spec, const StudyResult& result, std::size_t world);
/// Pairs of runs of two strategies on the same seed that both reached 95 %: the mean
/// difference, the paired t-test and how often each was faster.
StudyTable paired_table(const StudySpec& spec, const StudyResult& result, std::size_t world);

std::string to_markdown(const StudyTable& table);

}  // namespace lookahead::exploration
