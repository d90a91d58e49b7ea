// SPDX-License-Identifier: MIT
// report.html of a study: one self-contained page in the study folder (inline style, no
// script, no network) with the overall outcome, per world the strategy table, Welch's and
// the paired comparisons, the mean coverage plot and every finished run's map as a
// thumbnail linking to the full picture. Images are referenced relative to the page
// (coverage_<world>.png, time_to_95.png, runs/<run>/map.png), so the folder can be copied
// and opened from the file system.
#pragma once

#include <string>

#include "lookahead/exploration/study.hpp"

namespace lookahead::exploration {

std::string study_report_html(const StudySpec& spec, const StudyResult& result);

/// `text` with &, <, >, " and ' as character references.
std::string html_escape(const std::string& text);

}  // namespace lookahead::exploration
