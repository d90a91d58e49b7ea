// SPDX-License-Identifier: MIT
#include "lookahead/slam/rbpf/hypothesis_weight.hpp"

#include <cmath>

namespace lookahead::slam {

HypothesisScore score_on_hypotheses(const OccupancyGrid& map, const Pose2& robot, const PreparedScan& scan,
                                    const std::vector<std::shared_ptr<const HypothesisMap>>& hypotheses,
                                    const std::vector<Pose2>& offsets, const LikelihoodFieldModel& model) {
  HypothesisScore score;
  if (hypotheses.empty()) return score;
  const Pose2 laser = robot.compose(scan.laser_offset);
  const double c = std::cos(laser.theta);
  const double s = std::sin(laser.theta);
  for (std::size_t i = 0; i < scan.x.size(); ++i) {
    const double wx = laser.x + c * scan.x[i] - s * scan.y[i];
    const double wy = laser.y + s * scan.x[i] + c * scan.y[i];
    if (map.is_known(map.cell_at(wx, wy))) continue;  // z_e: S1 scores it
    for (std::size_t j = 0; j < hypotheses.size(); ++j) {
      const Pose2 q = offsets[j].compose(Pose2{wx, wy, 0.0});
      const OccupancyGrid& h = hypotheses[j]->grid;
      if (!h.is_known(h.cell_at(q.x, q.y))) continue;
      bool hit = false;
      score.log_likelihood += model.end_point_log_likelihood(h, q.x, q.y, hit);
      ++score.predicted_beams;
      score.hits += hit ? 1 : 0;
      break;
    }
  }
  return score;
}

}  // namespace lookahead::slam
