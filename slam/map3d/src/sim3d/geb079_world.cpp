// SPDX-License-Identifier: MIT
#include "lookahead/slam/octree/octree_io.hpp"
#include "lookahead/slam/sim3d/world3d.hpp"

namespace lookahead::slam {

World3 load_geb079_world(const std::string& bt_path) {
  World3 w{"geb079", read_octomap(bt_path), {}};
  // The corridor runs along x from about -7 to 28 m, y in [-1, 1], floor at z = 0 (read off
  // a slice of the map at 0.3-1.5 m). Out along one side, a U-turn, back along the other.
  w.route = {{-5.5, 0.0, 0.0}, {26.0, 0.35, 0.0}, {26.3, -0.35, 0.0}, {-5.5, -0.3, 0.0}};
  return w;
}

}  // namespace lookahead::slam
