// SPDX-License-Identifier: MIT
// YAML configuration of `lookahead slam3d`: the 3D RBPF, the simulated Cave Crawler and the
// 3DTK reader. Unknown keys and bad values are errors naming the file, line, key and value.
#pragma once

#include <string>

#include "lookahead/slam/io/threedtk_reader.hpp"
#include "lookahead/slam/rbpf3d/rbpf3d_options.hpp"
#include "lookahead/slam/sim3d/cave_crawler_sim.hpp"

namespace lookahead::slam {

struct Slam3dOptions {
  Rbpf3dOptions filter;
  CaveCrawlerOptions robot;
  double world_resolution = 0.1;  ///< voxel side of the generated garage world [m]
  ThreeDtkOptions threedtk;
};

/// Reads options from a YAML file on top of `base` (keys left out keep their value).
Slam3dOptions load_slam3d_options(const std::string& path, const Slam3dOptions& base = {});
/// Same, from YAML text (`source` names it in errors).
Slam3dOptions parse_slam3d_options(const std::string& yaml, const std::string& source, const Slam3dOptions& base = {});
/// The options as YAML, with a comment per key (config/slam3d/default.yaml).
std::string dump_slam3d_options(const Slam3dOptions& options);

}  // namespace lookahead::slam
