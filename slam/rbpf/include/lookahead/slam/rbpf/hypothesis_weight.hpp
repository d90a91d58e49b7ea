// SPDX-License-Identifier: MIT
// The P-SLAM weight split (Chang et al. 2007, P-SLAM eq. (13), (21)-(23)): a scan's end points that land
// in cells the particle has explored are z_e, those that land in unexplored cells covered by
// a hypothesis are z_u. S1(z_e | m) is the filter's usual weight; this file scores
// S2(z_u | h) with the same likelihood-field model on the hypothesis map, and the hit ratio
// hr = |h n z_u| / |z_u| of the recovery rule.
#pragma once

#include <memory>
#include <vector>

#include "lookahead/slam/geometry/pose2.hpp"
#include "lookahead/slam/grid/hypothesis.hpp"
#include "lookahead/slam/grid/occupancy_grid.hpp"
#include "lookahead/slam/sensor/likelihood_field_model.hpp"

namespace lookahead::slam {

struct HypothesisScore {
  double log_likelihood = 0.0;  ///< tempered log S2(z_u | h)
  int predicted_beams = 0;      ///< |z_u|
  int hits = 0;                 ///< |h n z_u|: end points within the hit distance of a predicted wall
  [[nodiscard]] double hit_ratio() const {
    return predicted_beams > 0 ? static_cast<double>(hits) / predicted_beams : 0.0;
  }
};

/// Scores the scan from `robot` (in the particle's map frame) on the hypotheses. The
/// particle's own map decides z_e vs z_u; `offsets[j]` moves a point of the particle's frame
/// into hypothesis j's frame (the best particle's, sec. IV-B). The first hypothesis that
/// covers an end point scores it.
HypothesisScore score_on_hypotheses(const OccupancyGrid& map, const Pose2& robot, const PreparedScan& scan,
                                    const std::vector<std::shared_ptr<const HypothesisMap>>& hypotheses,
                                    const std::vector<Pose2>& offsets, const LikelihoodFieldModel& model);

}  // namespace lookahead::slam
