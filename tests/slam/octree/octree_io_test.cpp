// SPDX-License-Identifier: MIT
#include "lookahead/slam/octree/octree_io.hpp"

#include <gtest/gtest.h>
#include <octomap/OcTree.h>

#include <limits>

#include "../temp_file.hpp"
#include "lookahead/slam/io/parse_error.hpp"

namespace lookahead::slam {
namespace {

const std::string kGeb079 = std::string(LOOKAHEAD_SOURCE_DIR) + "/../shared/data/3d/octomap_share_data/geb079.bt";

TEST(OctreeIo, BinaryRoundTripKeepsTheClassification) {
  EvidenceOctree map;
  for (int i = 0; i < 300; ++i) {
    const OctreeKey k{static_cast<std::uint16_t>(32700 + i % 37), static_cast<std::uint16_t>(32768 + i / 37), 32768};
    map.update(k, i % 3 == 0);
  }
  test::TempPath file(".bt");
  write_octomap(map, file.str());
  const EvidenceOctree back = read_octomap(file.str());
  EXPECT_DOUBLE_EQ(back.grid().resolution(), map.grid().resolution());
  EXPECT_EQ(back.known_voxels(), map.known_voxels());
  map.for_each_voxel([&](const OctreeKey& k, float) { EXPECT_EQ(back.state(k), map.state(k)); });
}

TEST(OctreeIo, OtRoundTripKeepsTheLogOdds) {
  EvidenceOctree map;
  map.update({40000, 30000, 32768}, true);
  map.update({40001, 30000, 32768}, false);
  test::TempPath file(".ot");
  write_octomap(map, file.str());
  const EvidenceOctree back = read_octomap(file.str());
  EXPECT_FLOAT_EQ(*back.log_odds({40000, 30000, 32768}), *map.log_odds({40000, 30000, 32768}));
  EXPECT_FLOAT_EQ(*back.log_odds({40001, 30000, 32768}), *map.log_odds({40001, 30000, 32768}));
}

TEST(OctreeIo, MissingOrForeignFilesAreParseErrors) {
  EXPECT_THROW(read_octomap("/nonexistent/map.bt"), ParseError);
  test::TempPath junk(".bt");
  junk.write("this is not an octree\n");
  EXPECT_THROW(read_octomap(junk.str()), ParseError);
  test::TempPath other(".txt");
  other.write("x");
  EXPECT_THROW(read_octomap(other.str()), ParseError);
}

// The real map of Freiburg building 079: leaves, resolution and bounds as data/3d/SOURCES.md
// states them; OctoMap's merged leaves come back as the voxels they stand for.
TEST(OctreeIo, ReadsGeb079AsDocumented) {
  const EvidenceOctree map = read_octomap(kGeb079);
  EXPECT_DOUBLE_EQ(map.grid().resolution(), 0.08);
  std::size_t occupied = 0, free = 0;
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = -lo;
  map.for_each_voxel([&](const OctreeKey& k, float l) {
    (l > 0.0f ? occupied : free) += 1;
    const Eigen::Vector3d c = map.grid().centre_of(k);
    lo = lo.cwiseMin(c);
    hi = hi.cwiseMax(c);
  });
  octomap::OcTree ref(0.1);
  ASSERT_TRUE(ref.readBinary(kGeb079));
  std::size_t leaves[2] = {0, 0}, voxels[2] = {0, 0};
  for (auto it = ref.begin_leafs(); it != ref.end_leafs(); ++it) {
    const std::size_t side = std::size_t{1} << (16 - it.getDepth());
    const int occ = ref.isNodeOccupied(*it) ? 1 : 0;
    leaves[occ] += 1;
    voxels[occ] += side * side * side;
  }
  EXPECT_EQ(leaves[1], 143729U);
  EXPECT_EQ(leaves[0], 284415U);
  EXPECT_EQ(occupied, voxels[1]);
  EXPECT_EQ(free, voxels[0]);
  const double h = 0.04;  // half a voxel: SOURCES.md gives the outer faces
  EXPECT_NEAR(lo.x() - h, -8.00, 0.01);
  EXPECT_NEAR(hi.x() + h, 30.96, 0.01);
  EXPECT_NEAR(lo.y() - h, -7.52, 0.01);
  EXPECT_NEAR(hi.y() + h, 7.44, 0.01);
  EXPECT_NEAR(lo.z() - h, -0.32, 0.01);
  EXPECT_NEAR(hi.z() + h, 2.80, 0.01);
}

}  // namespace
}  // namespace lookahead::slam
