// SPDX-License-Identifier: MIT
#include "lookahead/predictor/prediction_picture.hpp"

#include <fmt/format.h>

#include <cmath>

#include "lookahead/slam/io/map_io.hpp"

namespace lookahead::predictor {
namespace {

slam::PicturePath circle(double cx, double cy, double r, slam::Rgb colour, const std::string& label) {
  slam::PicturePath p{{}, colour, label, 2, false};
  for (int i = 0; i <= 72; ++i) {
    const double a = 2 * M_PI * i / 72;
    p.poses.push_back({cx + r * std::cos(a), cy + r * std::sin(a), 0.0});
  }
  return p;
}

}  // namespace

std::vector<slam::PicturePoints> predicted_cell_overlays(const slam::OccupancyGrid& predicted,
                                                         double occupied_threshold,
                                                         const std::function<bool(slam::CellIndex)>& show) {
  slam::PicturePoints walls{{}, {30, 70, 230}, "predicted wall", 1, true};
  slam::PicturePoints free{{}, {170, 205, 250}, "predicted free", 1, true};
  slam::CellIndex lo, hi;
  if (predicted.known_bounds(lo, hi)) {
    for (int y = lo.y; y <= hi.y; ++y) {
      for (int x = lo.x; x <= hi.x; ++x) {
        if (!predicted.is_known({x, y}) || (show && !show({x, y}))) continue;
        double cx = 0, cy = 0;
        predicted.cell_center({x, y}, cx, cy);
        (predicted.probability({x, y}) >= occupied_threshold ? walls : free).points.push_back({cx, cy});
      }
    }
  }
  return {free, walls};  // walls drawn last, over the free cells
}

void write_prediction_picture(const std::string& png_path, const slam::OccupancyGrid& map, const Prediction& p,
                              const PredictorOptions& o, const std::vector<slam::PicturePoints>& extra) {
  const double r = (p.diameter > 0 ? p.diameter : o.surroundings_diameter) / 2;  // the scale that was registered last
  std::vector<slam::PicturePath> paths{circle(p.target_x, p.target_y, r, {230, 120, 0}, "target region S_f")};
  std::vector<slam::PicturePoints> points = extra;  // under the hypothesis
  if (p.hypothesis) {
    for (auto& layer : predicted_cell_overlays(p.hypothesis->grid, o.features.occupied_threshold))
      points.push_back(layer);
  }
  slam::PicturePoints corners{{}, {150, 60, 170}, "corner features", 3, false};
  for (const Corner& c : p.features.corners) corners.points.push_back({c.x, c.y});
  points.push_back(corners);
  points.push_back({{{p.target_x, p.target_y}}, {230, 120, 0}, "target frontier cell f", 5, false});
  if (p.alignment) {
    const slam::Pose2 f_ref = p.alignment->reference_to_target.inverse().compose({p.target_x, p.target_y, 0});
    paths.push_back(circle(f_ref.x, f_ref.y, r, {0, 150, 60}, "reference region C_f'"));
    points.push_back({{{p.alignment->control.x, p.alignment->control.y}}, {220, 30, 30}, "control point P1", 5, false});
    points.push_back(
        {{{p.alignment->reference.x, p.alignment->reference.y}}, {0, 150, 60}, "reference point P2", 5, false});
  }
  const std::string title = fmt::format("P-SLAM prediction: {}{}", to_string(p.status),
                                        p.alignment ? fmt::format(", Psi = {:.2f}", p.alignment->score.psi) : "");
  // The picture spans the map and both regions, whichever reaches farther.
  slam::OccupancyGrid extent = map;
  for (const slam::PicturePath& c : paths) {
    for (const slam::Pose2& q : c.poses) {
      const slam::CellIndex cell = extent.cell_at(q.x, q.y);
      if (!extent.is_known(cell)) extent.mutable_tile(cell.x >> slam::GridTile::kBits, cell.y >> slam::GridTile::kBits);
    }
  }
  slam::write_map_picture(png_path, slam::to_probability_map(extent, 4), paths, title, points);
}

}  // namespace lookahead::predictor
