// SPDX-License-Identifier: MIT
#pragma once

namespace lookahead::app {

/// Peak resident memory of this process so far [MB] (VmHWM), 0 where unavailable.
double peak_memory_mb();

}  // namespace lookahead::app
