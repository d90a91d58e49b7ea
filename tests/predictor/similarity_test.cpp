// SPDX-License-Identifier: MIT
#include "lookahead/predictor/similarity.hpp"

#include <gtest/gtest.h>

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

TEST(Similarity, RejectsACoarserMapThanTheRaster) {
  EXPECT_THROW(CoarseOccupancy(slam::OccupancyGrid{}, 0.01, 0.65, 1), std::invalid_argument);
}

}  // namespace
}  // namespace lookahead::predictor
