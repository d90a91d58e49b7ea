// SPDX-License-Identifier: MIT
#include "lookahead/exploration/hypothesis_pictures.hpp"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>

#include "lookahead/predictor/prediction_picture.hpp"
#include "lookahead/slam/io/map_io.hpp"

namespace lookahead::exploration {
namespace {

// The world's walls within the target region S_f.
slam::PicturePoints true_walls(const World& world, double tx, double ty, double radius) {
  slam::PicturePoints walls{{}, {240, 170, 170}, "true walls in S_f", 1, true};
  const int r = static_cast<int>(std::ceil(radius / world.resolution()));
  const slam::CellIndex t = world.cell_of({tx, ty});
  for (int dy = -r; dy <= r; ++dy) {
    for (int dx = -r; dx <= r; ++dx) {
      if (dx * dx + dy * dy > r * r || !world.is_occupied(slam::CellIndex{t.x + dx, t.y + dy})) continue;
      const Eigen::Vector2d p = world.origin() + world.resolution() * Eigen::Vector2d(t.x + dx + 0.5, t.y + dy + 0.5);
      walls.points.push_back({p.x(), p.y()});
    }
  }
  return walls;
}

}  // namespace

void write_hypothesis_pictures(const LookaheadMapping& lookahead, const World& world, const std::string& dir) {
  if (lookahead.snapshots().empty()) return;
  std::filesystem::create_directories(dir);
  const predictor::PredictorOptions& o = lookahead.options().predictor;
  std::size_t n = 0;
  for (const HypothesisSnapshot& s : lookahead.snapshots()) {
    const PredictionRecord& r = lookahead.records()[s.record];
    const predictor::Prediction& p = s.prediction;
    const auto walls = true_walls(world, r.x, r.y, (p.diameter > 0 ? p.diameter : o.surroundings_diameter) / 2);
    const std::string name = fmt::format("{:03d}", n++);
    predictor::write_prediction_picture(dir + "/" + name + ".png", s.map, p, o, {walls});
    // The map it was made on: `lookahead predict DIR/NNN.yaml --target X,Y` repeats it.
    slam::write_map(slam::to_probability_map(s.map), dir, name);
  }
}

}  // namespace lookahead::exploration
