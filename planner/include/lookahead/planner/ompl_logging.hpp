// SPDX-License-Identifier: MIT
// OMPL prints every planner start and stop to the console at its default level. That level
// is process-wide, so the library never changes it itself: apps (and tests) call this once.
#pragma once

namespace lookahead::planner {

enum class OmplLogLevel { kDebug, kInfo, kWarn, kError, kNone };

/// Sets OMPL's process-wide console level (OMPL's default is kInfo).
void set_ompl_log_level(OmplLogLevel level);

}  // namespace lookahead::planner
