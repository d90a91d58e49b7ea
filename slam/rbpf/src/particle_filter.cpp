// SPDX-License-Identifier: MIT
#include "lookahead/slam/rbpf/particle_filter.hpp"

namespace lookahead::slam {

bool should_resample(double neff, double threshold, std::size_t particles) {
  // Written as "not enough", so a NaN N_eff (degenerate weights) resamples.
  return !(neff >= threshold * static_cast<double>(particles));
}

}  // namespace lookahead::slam
