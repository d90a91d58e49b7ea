// SPDX-License-Identifier: MIT
#include "lookahead/slam/octree/octree_top_view.hpp"

#include <algorithm>
#include <climits>
#include <map>

namespace lookahead::slam {

ProbabilityMap top_view(const EvidenceOctree& map, double wall_height, int margin_cells, int upsample) {
  struct Column {
    int occupied = 0;
    bool free = false;
  };
  std::map<std::pair<int, int>, Column> columns;
  int x0 = INT_MAX, y0 = INT_MAX, x1 = INT_MIN, y1 = INT_MIN;
  const auto occupied_above = static_cast<float>(map.options().occupied_above);
  map.for_each_voxel([&](const OctreeKey& k, float l) {
    Column& c = columns[{k.x, k.y}];
    if (l > occupied_above) {
      ++c.occupied;
    } else {
      c.free = true;
    }
    x0 = std::min<int>(x0, k.x), x1 = std::max<int>(x1, k.x);
    y0 = std::min<int>(y0, k.y), y1 = std::max<int>(y1, k.y);
  });
  ProbabilityMap out;
  out.resolution = map.grid().resolution();
  if (columns.empty()) return out;
  x0 -= margin_cells, y0 -= margin_cells, x1 += margin_cells, y1 += margin_cells;
  // Room above the map for the picture's legend, which sits in the top-left corner.
  y1 += (x1 - x0) / 5;
  const int f = std::max(1, upsample);
  out.resolution /= f;
  out.width = (x1 - x0 + 1) * f;
  out.height = (y1 - y0 + 1) * f;
  out.origin_x = map.grid().axis_centre(x0) - 0.5 * map.grid().resolution();
  out.origin_y = map.grid().axis_centre(y0) - 0.5 * map.grid().resolution();
  out.p.assign(static_cast<std::size_t>(out.width) * static_cast<std::size_t>(out.height), 0.5);
  const int wall_voxels = std::max(1, static_cast<int>(wall_height / map.grid().resolution() + 0.5));
  for (const auto& [xy, c] : columns) {
    if (c.occupied < wall_voxels && !c.free) continue;
    const double value = c.occupied >= wall_voxels ? 1.0 : 0.0;
    for (int dy = 0; dy < f; ++dy)
      for (int dx = 0; dx < f; ++dx)
        out.p[static_cast<std::size_t>(((xy.second - y0) * f + dy) * out.width + (xy.first - x0) * f + dx)] = value;
  }
  return out;
}

}  // namespace lookahead::slam
