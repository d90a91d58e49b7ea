// SPDX-License-Identifier: MIT
#include "lookahead/exploration/mission_picture.hpp"

#include <cmath>

#include "lookahead/predictor/prediction_picture.hpp"

namespace lookahead::exploration {

slam::ProbabilityMap map_over_world(const slam::OccupancyGrid& map, const World& world) {
  slam::ProbabilityMap m;
  m.resolution = map.resolution();
  m.origin_x = world.origin().x();
  m.origin_y = world.origin().y();
  m.width = static_cast<int>(std::ceil(world.width_m() / m.resolution));
  m.height = static_cast<int>(std::ceil(world.height_m() / m.resolution));
  m.p.resize(static_cast<std::size_t>(m.width) * static_cast<std::size_t>(m.height));
  for (int y = 0; y < m.height; ++y) {
    for (int x = 0; x < m.width; ++x) {
      const double wx = m.origin_x + (x + 0.5) * m.resolution, wy = m.origin_y + (y + 0.5) * m.resolution;
      const slam::CellIndex c = map.cell_at(wx, wy);
      double p = map.is_known(c) ? map.probability(c) : -1.0;
      // Unknown space shows the true walls faintly (p = 0.5 renders mid-grey under the tint
      // of unknown), so a reader sees what is left to explore.
      if (p < 0 && world.is_occupied(wx, wy)) p = -0.5;
      m.p[static_cast<std::size_t>(y) * static_cast<std::size_t>(m.width) + static_cast<std::size_t>(x)] = p;
    }
  }
  return m;
}

slam::BgrImage render_mission(const Mission& mission, const std::string& title) {
  const slam::ProbabilityMap m = map_over_world(mission.map(), mission.world());
  std::vector<slam::PicturePath> paths{
      {mission.true_path(), {40, 90, 220}, "true path", 2},
  };
  if (mission.slam()) paths.push_back({mission.estimated_path(), {210, 40, 40}, "SLAM estimate", 1});
  if (const planner::Path* p = mission.current_path()) {
    std::vector<slam::Pose2> planned;
    for (const auto& q : *p) planned.push_back({q.x, q.y, 0.0});
    paths.push_back({planned, {20, 170, 90}, "planned path", 1});
  }
  slam::PicturePoints frontier{{}, {220, 0, 220}, "frontier cells", 1};
  for (const slam::CellIndex c : mission.frontiers().cells()) {
    double x, y;
    mission.map().cell_center(c, x, y);
    frontier.points.push_back({x, y});
  }
  std::vector<slam::PicturePoints> points;
  if (const LookaheadMapping* la = mission.lookahead()) {
    // Predicted cells the robot has not explored yet, in colour beside the explored map.
    const PredictedMap& pm = la->predicted();
    points = predictor::predicted_cell_overlays(pm.cells(), la->options().predictor.features.occupied_threshold,
                                                [&](slam::CellIndex c) { return pm.predicted(mission.map(), c); });
  }
  points.push_back(frontier);
  if (!mission.escape_spots().empty()) {
    slam::PicturePoints escapes{{}, {0, 200, 255}, "stop escape (turn, then creep)", 4};
    for (const planner::Point2& e : mission.escape_spots()) escapes.points.push_back({e.x, e.y});
    points.push_back(escapes);
  }
  if (mission.goal()) points.push_back({{{mission.goal()->x, mission.goal()->y}}, {255, 140, 0}, "goal", 5});
  return slam::render_map_picture(m, paths, points, title);
}

}  // namespace lookahead::exploration
