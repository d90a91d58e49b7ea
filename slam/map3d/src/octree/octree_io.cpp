// SPDX-License-Identifier: MIT
#include "lookahead/slam/octree/octree_io.hpp"

#include <octomap/OcTree.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>

#include "lookahead/slam/io/parse_error.hpp"

namespace lookahead::slam {
namespace {

bool has_extension(const std::string& path, const char* ext) { return std::filesystem::path(path).extension() == ext; }

double log_odds_of(double p) { return std::log(p / (1.0 - p)); }

std::unique_ptr<octomap::OcTree> load_tree(const std::string& path) {
  if (!std::filesystem::exists(path)) throw ParseError(path, 0, "", "", "no such file");
  if (has_extension(path, ".bt")) {
    std::ifstream in(path, std::ios::binary);
    auto tree = std::make_unique<octomap::OcTree>(0.1);
    if (!tree->readBinary(in)) throw ParseError(path, 0, "", "", "not an OctoMap binary (.bt) OcTree");
    return tree;
  }
  if (has_extension(path, ".ot")) {
    std::unique_ptr<octomap::AbstractOcTree> any(octomap::AbstractOcTree::read(path));
    auto* tree = dynamic_cast<octomap::OcTree*>(any.get());
    if (!tree) throw ParseError(path, 0, "", "", "not an OctoMap OcTree (.ot)");
    any.release();
    return std::unique_ptr<octomap::OcTree>(tree);
  }
  throw ParseError(path, 0, "extension", std::filesystem::path(path).extension().string(), "expected .bt or .ot");
}

}  // namespace

EvidenceOctree read_octomap(const std::string& path) {
  const std::unique_ptr<octomap::OcTree> tree = load_tree(path);
  OctreeOptions o;
  o.resolution = tree->getResolution();
  o.log_odds_hit = log_odds_of(tree->getProbHit());
  o.log_odds_miss = log_odds_of(tree->getProbMiss());
  o.log_odds_min = tree->getClampingThresMinLog();
  o.log_odds_max = tree->getClampingThresMaxLog();
  o.occupied_above = tree->getOccupancyThresLog();
  EvidenceOctree map(o);
  OctreeWriter writer(map);
  const unsigned max_depth = tree->getTreeDepth();
  for (auto it = tree->begin_leafs(), end = tree->end_leafs(); it != end; ++it) {
    // A leaf above the finest depth stands for a cube of 2^(16 - depth) voxels per side.
    const int side = 1 << (max_depth - it.getDepth());
    const octomap::OcTreeKey base = it.getIndexKey();
    const float value = it->getLogOdds();
    for (int dz = 0; dz < side; ++dz)
      for (int dy = 0; dy < side; ++dy)
        for (int dx = 0; dx < side; ++dx)
          writer.set_log_odds({static_cast<std::uint16_t>(base[0] + dx), static_cast<std::uint16_t>(base[1] + dy),
                               static_cast<std::uint16_t>(base[2] + dz)},
                              value);
  }
  return map;
}

void write_octomap(const EvidenceOctree& map, const std::string& path) {
  const OctreeOptions& o = map.options();
  octomap::OcTree tree(o.resolution);
  tree.setProbHit(1.0 - 1.0 / (1.0 + std::exp(o.log_odds_hit)));
  tree.setProbMiss(1.0 - 1.0 / (1.0 + std::exp(o.log_odds_miss)));
  tree.setClampingThresMin(1.0 - 1.0 / (1.0 + std::exp(o.log_odds_min)));
  tree.setClampingThresMax(1.0 - 1.0 / (1.0 + std::exp(o.log_odds_max)));
  tree.setOccupancyThres(1.0 - 1.0 / (1.0 + std::exp(o.occupied_above)));
  map.for_each_voxel([&](const OctreeKey& k, float l) {
    tree.setNodeValue(octomap::OcTreeKey(k.x, k.y, k.z), l, /*lazy_eval=*/true);
  });
  tree.updateInnerOccupancy();
  if (const auto dir = std::filesystem::path(path).parent_path(); !dir.empty()) {
    std::filesystem::create_directories(dir);
  }
  bool ok = false;
  if (has_extension(path, ".bt")) {
    tree.prune();
    ok = tree.writeBinary(path);
  } else if (has_extension(path, ".ot")) {
    ok = tree.write(path);
  } else {
    throw std::invalid_argument(path + ": expected a .bt or .ot file name");
  }
  if (!ok) throw std::runtime_error(path + ": cannot write the OctoMap file");
}

}  // namespace lookahead::slam
