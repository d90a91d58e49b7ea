// SPDX-License-Identifier: MIT
#include "lookahead/predictor/similarity.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "square_maze_grid.hpp"

namespace lookahead::predictor {
namespace {

using test::kPeriod;

TEST(Similarity, RegionComparedWithItselfIsOne) {
  const slam::OccupancyGrid g = test::maze_grid(30.0);
  const CoarseOccupancy c(g, 0.1, 0.65, 0);
  const SimilarityScore s = similarity(c, c, disc_samples(8, 8, 10, 0.1), {});
  EXPECT_GT(s.target_occupied, 100);
  EXPECT_DOUBLE_EQ(s.psi, 1.0);
}

TEST(Similarity, OnePeriodShiftOfAPeriodicMazeMatches) {
  const slam::OccupancyGrid g = test::maze_grid(30.0);
  const CoarseOccupancy c(g, 0.1, 0.65, 1);
  EXPECT_GT(similarity(c, c, disc_samples(14, 14, 10, 0.1), {-kPeriod, 0, 0}).psi, 0.9);
  // A quarter turn about the centre of a corridor crossing, (12.5, 12.5), is a symmetry too.
  EXPECT_GT(similarity(c, c, disc_samples(14, 14, 10, 0.1), {25.0, 0, M_PI / 2}).psi, 0.9);
}

TEST(Similarity, HalfAPeriodShiftDoesNotMatch) {
  const slam::OccupancyGrid g = test::maze_grid(30.0);
  const CoarseOccupancy c(g, 0.1, 0.65, 1);
  EXPECT_LT(similarity(c, c, disc_samples(8, 8, 10, 0.1), {kPeriod / 2, 0, 0}).psi, 0.4);
}

TEST(Similarity, ToleranceForgivesOneCellOfMisalignment) {
  const slam::OccupancyGrid g = test::maze_grid(30.0);
  const CoarseOccupancy exact(g, 0.1, 0.65, 0), tolerant(g, 0.1, 0.65, 1);
  const slam::Pose2 off{-kPeriod + 0.1, 0, 0};
  const double psi_exact = similarity(exact, exact, disc_samples(14, 14, 10, 0.1), off).psi;
  const double psi_tolerant = similarity(tolerant, tolerant, disc_samples(14, 14, 10, 0.1), off).psi;
  EXPECT_LT(psi_exact, 0.8);
  EXPECT_GT(psi_tolerant, 0.9);
}

TEST(Similarity, EmptyReferenceScoresZeroAndCountsNewCells) {
  const slam::OccupancyGrid g = test::maze_grid(30.0);
  const CoarseOccupancy c(g, 0.1, 0.65, 1), empty(slam::OccupancyGrid{}, 0.1, 0.65, 1);
  const SimilarityScore s = similarity(c, empty, disc_samples(8, 8, 10, 0.1), {});
  EXPECT_EQ(s.reference_occupied, 0);
  EXPECT_DOUBLE_EQ(s.psi, 0.0);
  const SimilarityScore n = similarity(empty, c, disc_samples(8, 8, 10, 0.1), {});
  EXPECT_GT(n.new_known, 4000);  // every known cell of the disc is new to the empty target
}

// A registration reads the target's cells once (TargetRegion) and scores hundreds of
// alignments against it: the score is the same as reading both maps per sample.
TEST(Similarity, ATargetReadOnceScoresAsReadingItPerSample) {
  const slam::OccupancyGrid g = test::maze_grid(20.0);  // explored to x = 20 m: some samples new
  const CoarseOccupancy c(g, 0.1, 0.65, 1);
  const RegionSamples region = disc_samples(14, 14, 10, 0.1);
  const TargetRegion target(c, region);
  for (const slam::Pose2 t : {slam::Pose2{}, slam::Pose2{-kPeriod, 0, 0}, slam::Pose2{0.37, -1.2, 0.4}}) {
    SimilarityScore per_sample;
    int shared = 0;
    const slam::Pose2 inv = t.inverse();
    const double cs = std::cos(inv.theta), sn = std::sin(inv.theta);
    for (std::size_t k = 0; k < region.x.size(); ++k) {
      const double px = region.x[k], py = region.y[k];
      const slam::Pose2 q{inv.x + cs * px - sn * py, inv.y + sn * px + cs * py, 0.0};
      const bool t_occ = c.occupied(region.x[k], region.y[k]), r_occ = c.occupied(q.x, q.y);
      per_sample.target_occupied += t_occ;
      per_sample.reference_occupied += r_occ;
      shared += (t_occ && c.near_occupied(q.x, q.y)) + (r_occ && c.near_occupied(region.x[k], region.y[k]));
      per_sample.new_known += !c.known(region.x[k], region.y[k]) && c.known(q.x, q.y);
    }
    const SimilarityScore s = similarity(target, c, t);
    EXPECT_EQ(s.target_occupied, per_sample.target_occupied);
    EXPECT_EQ(s.reference_occupied, per_sample.reference_occupied);
    EXPECT_EQ(s.new_known, per_sample.new_known);
    EXPECT_NEAR(s.psi, static_cast<double>(shared) / (per_sample.target_occupied + per_sample.reference_occupied),
                1e-12);
  }
}

TEST(Similarity, RejectsACoarserMapThanTheRaster) {
  EXPECT_THROW(CoarseOccupancy(slam::OccupancyGrid{}, 0.01, 0.65, 1), std::invalid_argument);
}

}  // namespace
}  // namespace lookahead::predictor
