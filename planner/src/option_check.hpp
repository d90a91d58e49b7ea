// SPDX-License-Identifier: MIT
// Range checks shared by the option validators: one message shape everywhere, naming the
// field, the value and the accepted range.
#pragma once

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace lookahead::planner::detail {

enum class Bound { kClosed, kOpen };

/// Throws std::invalid_argument unless lo (<|<=) value <= hi and value is finite.
inline void check_range(const char* field, double value, double lo, double hi, const char* unit,
                        Bound lower = Bound::kClosed) {
  const bool above_lo = lower == Bound::kOpen ? value > lo : value >= lo;
  if (std::isfinite(value) && above_lo && value <= hi) return;
  std::ostringstream msg;
  msg << field << " = " << value << " is outside " << (lower == Bound::kOpen ? "(" : "[") << lo << ", " << hi << "]";
  if (unit[0] != '\0') msg << ' ' << unit;
  throw std::invalid_argument(msg.str());
}

}  // namespace lookahead::planner::detail
