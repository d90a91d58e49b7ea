// SPDX-License-Identifier: MIT
// P-SLAM look-ahead mapping in missions: the predicted map validates itself as the robot
// explores, the predictive strategy skips what is predicted and nothing else, hypotheses are
// checked against the world, and a mission with predictions on makes and scores them.
#include <gtest/gtest.h>

#include "lookahead/exploration/generated_worlds.hpp"
#include "lookahead/exploration/hypothesis_check.hpp"
#include "lookahead/exploration/mission.hpp"
#include "lookahead/exploration/mission_report.hpp"
#include "lookahead/exploration/predicted_map.hpp"
#include "lookahead/exploration/prediction_aware_strategy.hpp"
#include "lookahead/exploration/region_flood.hpp"
#include "lookahead/exploration/world_reachability.hpp"

namespace lookahead::exploration {
namespace {

slam::HypothesisMap hypothesis(double x0, double x1, double psi, int log_odds) {
  slam::HypothesisMap h;
  for (double y = 0.025; y < 1.0; y += 0.05)
    for (double x = x0 + 0.025; x < x1; x += 0.05) h.grid.add_log_odds(h.grid.cell_at(x, y), log_odds);
  h.similarity = psi;
  return h;
}

TEST(PredictedMap, ExploredCellsLeaveThePrediction) {
  PredictedMap pm;
  pm.add(hypothesis(0.0, 2.0, 0.7, -1000));
  slam::OccupancyGrid map;
  const slam::CellIndex c = map.cell_at(0.5, 0.5);
  EXPECT_TRUE(pm.predicted(map, c));
  EXPECT_DOUBLE_EQ(pm.confidence(c), static_cast<double>(0.7f));
  map.add_log_odds(c, -500);  // the robot has seen it now
  EXPECT_FALSE(pm.predicted(map, c));
  EXPECT_FALSE(pm.predicted(map, map.cell_at(3.0, 0.5)));  // never predicted
}

TEST(PredictedMap, TheMoreSimilarHypothesisWinsWhereTheyOverlap) {
  PredictedMap pm;
  pm.add(hypothesis(0.0, 2.0, 0.9, 2000));   // a wall, Psi 0.9
  pm.add(hypothesis(1.0, 3.0, 0.6, -1000));  // free, Psi 0.6: loses on [1, 2]
  const slam::OccupancyGrid map;
  EXPECT_GT(pm.cells().probability(map.cell_at(1.5, 0.5)), 0.65);
  EXPECT_LT(pm.cells().probability(map.cell_at(2.5, 0.5)), 0.35);
  pm.add(hypothesis(0.0, 1.0, 0.95, -1000));  // a better one replaces the wall
  EXPECT_LT(pm.cells().probability(map.cell_at(0.5, 0.5)), 0.35);
  EXPECT_EQ(pm.hypotheses(), 3u);
}

TEST(PredictedMap, PredictedShareCountsTheUnknownSideOfAFrontier) {
  slam::OccupancyGrid map;
  FrontierCluster cluster;
  for (int y = 0; y < 20; ++y) {  // a frontier along x = 0 facing +x (unknown at x >= 0.05)
    const slam::CellIndex c{0, y};
    map.add_log_odds(c, -1000);
    map.add_log_odds({-1, y}, -1000);
    cluster.cells.push_back(c);
  }
  PredictedMap pm;
  EXPECT_DOUBLE_EQ(pm.predicted_share(map, cluster, 0.6), 0.0);
  pm.add(hypothesis(0.05, 1.0, 0.7, -1000));                     // covers y in [0, 1): all 20 cells' right side
  EXPECT_GT(pm.predicted_share(map, cluster, 0.6), 0.6);         // right neighbours, not the ends
  EXPECT_DOUBLE_EQ(pm.predicted_share(map, cluster, 0.8), 0.0);  // not confident enough
}

TEST(PredictedMap, ARegionIsCoveredWhenPredictedOrClosedByAPredictedWall) {
  slam::OccupancyGrid map;
  FrontierCluster cluster;
  for (int y = 0; y < 20; ++y) {  // the frontier above, its goal on it at (0, 0.5)
    map.add_log_odds({0, y}, -1000);
    map.add_log_odds({-1, y}, -1000);
    cluster.cells.push_back({0, y});
  }
  cluster.has_goal = true;
  cluster.goal_y = 0.5;
  const SkipRule rule = SkipRule::region(0.5).with_region_tolerance(0.1);  // region: 0.5 m round the goal
  PredictedMap none;
  EXPECT_NEAR(none.unpredicted_area(map, cluster, 0.5, 0.6, 0.65), 0.39, 0.03);  // the half disc
  EXPECT_DOUBLE_EQ(none.covered_share(map, cluster, rule), 0.0);
  PredictedMap part;
  part.add(hypothesis(0.05, 0.3, 0.7, -1000));                    // free up to x = 0.3: the rest is unknown
  EXPECT_GT(part.predicted_share(map, cluster, 0.6), 0.9);        // its far side looks covered ...
  EXPECT_DOUBLE_EQ(part.covered_share(map, cluster, rule), 0.0);  // ... its region is not
  PredictedMap free_region;
  free_region.add(hypothesis(0.05, 1.0, 0.7, -1000));
  EXPECT_DOUBLE_EQ(free_region.covered_share(map, cluster, rule), 1.0);
  EXPECT_DOUBLE_EQ(free_region.covered_share(map, cluster,
                                             SkipRule::region(0.5).with_min_confidence(0.8).with_region_tolerance(0.1)),
                   0.0);  // Psi too low
  PredictedMap wall;
  wall.add(hypothesis(0.05, 0.1, 0.7, 2000));  // a wall right beyond the frontier closes it
  EXPECT_LT(wall.unpredicted_area(map, cluster, 0.5, 0.6, 0.65), 0.01);
  EXPECT_DOUBLE_EQ(wall.covered_share(map, cluster, rule), 1.0);
  // The far-side variant reads only the cells beside the frontier, all predicted here.
  EXPECT_DOUBLE_EQ(part.covered_share(map, cluster, SkipRule::far_side().with_region_tolerance(0.1)),
                   part.predicted_share(map, cluster, 0.6));
  const RegionArea a = part.region_area(map, cluster, rule);
  EXPECT_NEAR(a.predicted + a.unpredicted, 0.39, 0.03);  // the half disc, split
  EXPECT_GT(a.predicted, 0.05);
}

// Deciding needs only the start of the flood: once more is unpredicted than the tolerance,
// no rule leaves the region out, and the flood stops there with the same answer.
TEST(PredictedMap, AFloodStopsOnceTooMuchIsUnpredicted) {
  slam::OccupancyGrid map;
  FrontierCluster cluster;
  for (int y = 0; y < 20; ++y) {
    map.add_log_odds({0, y}, -1000);
    map.add_log_odds({-1, y}, -1000);
    cluster.cells.push_back({0, y});
  }
  cluster.has_goal = true;
  cluster.goal_y = 0.5;
  const SkipRule rule = SkipRule::region(3.0).with_region_tolerance(0.1);
  PredictedMap none;
  const RegionArea whole = flood_region(map, none, cluster, rule);
  const RegionArea stopped = flood_region(map, none, cluster, rule, 0.1);
  EXPECT_GT(whole.unpredicted, 10.0);  // the half disc of 3 m
  EXPECT_GT(stopped.unpredicted, 0.1);
  EXPECT_LT(stopped.unpredicted, 0.2);  // a few cells past the tolerance
  EXPECT_EQ(left_out(whole, rule), left_out(stopped, rule));
}

// A frontier whose far side has been seen since the frontiers were found has an empty
// region: nothing in it is predicted, so no prediction leaves it out (counting it covered
// would skip every stale frontier and end a mission with most of the building unexplored).
TEST(PredictedMap, AnEmptyRegionIsNotCoveredByPrediction) {
  slam::OccupancyGrid map;
  FrontierCluster cluster;
  for (int y = -20; y < 40; ++y) {
    for (int x = -5; x < 40; ++x) map.add_log_odds({x, y}, -1000);  // all seen, free
  }
  for (int y = 0; y < 20; ++y) cluster.cells.push_back({0, y});  // a stale frontier
  cluster.has_goal = true;
  cluster.goal_y = 0.5;
  const SkipRule rule = SkipRule::region(0.5).with_region_tolerance(0.1);
  PredictedMap none;
  const RegionArea a = none.region_area(map, cluster, rule);
  EXPECT_DOUBLE_EQ(a.predicted + a.unpredicted, 0.0);
  EXPECT_DOUBLE_EQ(none.covered_share(map, cluster, rule), 0.0);
  EXPECT_FALSE(a.covered(1.0));
  EXPECT_TRUE((RegionArea{0.0, 0.0, true}).covered(0.0));  // a predicted wall closing it touches it
  EXPECT_FALSE((RegionArea{0.5, 1.5, false}).covered(1.0));
}

// A wall 0.25 m beyond the frontier with a three-cell (0.15 m) gap, as a wall seen from afar
// has between beams: the region leaks through it unless such gaps count as wall.
TEST(PredictedMap, AGapInAWallClosesTheRegionWithWallGap) {
  slam::OccupancyGrid map;
  FrontierCluster cluster;
  for (int y = -30; y <= 50; ++y) {  // an explored strip, its middle 1 m the frontier
    map.add_log_odds({0, y}, -1000);
    map.add_log_odds({-1, y}, -1000);
    if (y >= 0 && y < 20) cluster.cells.push_back({0, y});
  }
  cluster.has_goal = true;
  cluster.goal_y = 0.5;
  for (int y = -30; y <= 50; ++y)
    if (y < 9 || y > 11) map.add_log_odds({5, y}, 2000);
  const PredictedMap none;
  SkipRule rule = SkipRule::region(1.0).with_region_tolerance(0.1);
  EXPECT_GT(none.region_area(map, cluster, rule).unpredicted, 1.0);  // the far side of the wall too
  rule.wall_gap = 0.3;
  EXPECT_LT(none.region_area(map, cluster, rule).unpredicted, 0.5);  // only the strip before it
  EXPECT_GT(none.region_area(map, cluster, rule).unpredicted, 0.05);
}

// A frontier facing the unseen outside of the building: its region leaks beyond the outer
// wall, where nothing can be predicted, unless the boundary is known (P-SLAM Fig. 7(d)).
TEST(PredictedMap, AKnownBoundaryEndsTheRegion) {
  slam::OccupancyGrid map;
  FrontierCluster cluster;
  for (int y = -30; y <= 50; ++y) {  // an explored strip at x = -0.05..0.05, its middle 1 m the frontier
    map.add_log_odds({0, y}, -1000);
    map.add_log_odds({-1, y}, -1000);
    if (y >= 0 && y < 20) cluster.cells.push_back({0, y});
  }
  cluster.has_goal = true;
  cluster.goal_y = 0.5;
  PredictedMap pm;
  pm.add(hypothesis(0.05, 0.5, 0.7, -1000));  // the building's inside, up to x = 0.5, predicted
  SkipRule rule = SkipRule::region(1.0).with_region_tolerance(0.1);
  const RegionArea open = pm.region_area(map, cluster, rule);
  EXPECT_GT(open.unpredicted, 0.5);  // beyond x = 0.5: never predictable
  EXPECT_DOUBLE_EQ(pm.covered_share(map, cluster, rule), 0.0);
  rule.boundary = SkipRule::Extent{-5.0, 0.0, 0.5, 1.0};  // the building ends at x = 0.5, y = 0 and 1
  const RegionArea closed = pm.region_area(map, cluster, rule);
  EXPECT_LT(closed.unpredicted, 0.1);
  EXPECT_NEAR(closed.predicted, open.predicted, 1e-9);  // the inside is the same
  EXPECT_DOUBLE_EQ(pm.covered_share(map, cluster, rule), 1.0);
  const PredictedMap none;  // a boundary alone predicts nothing: the region is not left out
  EXPECT_DOUBLE_EQ(none.covered_share(map, cluster, rule), 0.0);
}

// A wall seen at a grazing angle: the frontier is the free strip's edge, a wall one cell
// beyond it has unknown cells between its beam end points. Its far side is unknown only in
// those gaps: with skip_wall_slivers it is left out as the wall running through them; a
// stale frontier (nothing unexplored beyond it) is not, nor a frontier open beyond the gap.
TEST(PredictedMap, AWallSliverIsLeftOutOnlyWhenAsked) {
  slam::OccupancyGrid map;
  FrontierCluster cluster;
  for (int y = -30; y <= 50; ++y) {
    map.add_log_odds({0, y}, -1000);
    map.add_log_odds({-1, y}, -1000);
    if (y >= 0 && y < 20) cluster.cells.push_back({0, y});
    if (y % 3 != 0) map.add_log_odds({2, y}, 2000);  // the wall 0.1 m on, every third cell unseen
  }
  cluster.has_goal = true;
  cluster.goal_y = 0.5;
  const PredictedMap none;
  SkipRule rule = SkipRule::region(1.0).with_region_tolerance(0.1).with_wall_gap(0.3);
  RegionArea a = none.region_area(map, cluster, rule);
  EXPECT_TRUE(a.wall_sliver(rule.region_tolerance));
  EXPECT_FALSE(left_out(a, rule));  // not without the option
  rule.skip_wall_slivers = true;
  EXPECT_TRUE(left_out(none.region_area(map, cluster, rule), rule));
  EXPECT_DOUBLE_EQ(none.covered_share(map, cluster, rule), 1.0);
  rule.wall_gap = 0.0;  // gaps open: the region leaks beyond the wall, not a sliver
  a = none.region_area(map, cluster, rule);
  EXPECT_GT(a.unpredicted, 0.5);
  EXPECT_FALSE(a.wall_sliver(rule.region_tolerance));
  EXPECT_FALSE(left_out(a, rule));
  EXPECT_FALSE((RegionArea{0.0, 0.0, false, false}).wall_sliver(0.1));       // stale: nothing unexplored
  EXPECT_FALSE((RegionArea{0.0, 0.5, false, true}).wall_sliver(0.1));        // more than a pocket
  EXPECT_TRUE((RegionArea{0.0, 0.05, false, false}).wall_sliver(0.1));       // a pocket closed by walls
  EXPECT_FALSE((RegionArea{0.05, 0.0, false, true}).wall_sliver(0.1));       // predicted: the covered rule's
  EXPECT_FALSE((RegionArea{0.0, 0.0, true, true}).wall_sliver(0.1));         // closed by a predicted wall: likewise
  EXPECT_FALSE((RegionArea{0.0, 0.0, false, true, true}).wall_sliver(0.1));  // in a predicted wall's gap
}

// The same frontier before a *predicted* wall 0.15 m on, unbroken: its unexplored neighbours
// lie within the gap width of that wall only. The prediction closes the region, not the
// robot's own map, so the sliver rule does not leave it out (a predicted wall across a
// corridor's mouth would otherwise cut off what lies beyond).
TEST(PredictedMap, APredictedWallMakesNoSliver) {
  slam::OccupancyGrid map;
  FrontierCluster cluster;
  slam::HypothesisMap wall;
  for (int y = -30; y <= 50; ++y) {
    map.add_log_odds({0, y}, -1000);
    map.add_log_odds({-1, y}, -1000);
    if (y >= 0 && y < 20) cluster.cells.push_back({0, y});
    wall.grid.add_log_odds({3, y}, 2000);
  }
  wall.similarity = 0.9;
  cluster.has_goal = true;
  cluster.goal_y = 0.5;
  PredictedMap pm;
  pm.add(wall);
  SkipRule rule = SkipRule::region(1.0).with_region_tolerance(0.1).with_wall_gap(0.3).with_wall_slivers(true);
  const RegionArea a = pm.region_area(map, cluster, rule);
  EXPECT_DOUBLE_EQ(a.unpredicted, 0.0);
  EXPECT_TRUE(a.gap_of_prediction);
  EXPECT_FALSE(left_out(a, rule));
  for (int y = -30; y <= 50; ++y) map.add_log_odds({3, y}, 2000);  // the robot sees that wall itself
  EXPECT_TRUE(left_out(pm.region_area(map, cluster, rule), rule));
}

// A frontier made only by a band of cells a grazing beam crossed (seen, neither free nor
// occupied; the frontier detector counts them unexplored) before an unbroken wall: without
// the sliver rule its region is empty and nothing leaves it out; with it, the band is the
// region, a pocket of 0.1 m^2, and the frontier is left out; a band open to a room is not.
TEST(PredictedMap, AnUndecidedBandBeforeAWallIsASliver) {
  slam::OccupancyGrid map;
  FrontierCluster cluster;
  for (int y = -30; y <= 50; ++y) {
    map.add_log_odds({0, y}, -1000);
    map.add_log_odds({-1, y}, -1000);
    map.add_log_odds({1, y}, 100);   // undecided: probability 0.52
    map.add_log_odds({2, y}, 2000);  // the wall, unbroken
    if (y >= 0 && y < 20) cluster.cells.push_back({0, y});
  }
  cluster.has_goal = true;
  cluster.goal_y = 0.5;
  const PredictedMap none;
  SkipRule rule = SkipRule::region(1.0).with_region_tolerance(0.1);
  const RegionArea before = none.region_area(map, cluster, rule);
  EXPECT_DOUBLE_EQ(before.unpredicted, 0.0);
  EXPECT_FALSE(before.closed_by_gap);
  rule.skip_wall_slivers = true;
  const RegionArea band = none.region_area(map, cluster, rule);
  EXPECT_NEAR(band.unpredicted, 0.1, 0.005);  // the band, one cell wide, within 1 m of the goal
  EXPECT_TRUE(left_out(band, rule));
  slam::OccupancyGrid open;  // the same band, the wall with a 2 m opening to unknown space
  for (int y = -30; y <= 50; ++y) {
    open.add_log_odds({0, y}, -1000);
    open.add_log_odds({-1, y}, -1000);
    open.add_log_odds({1, y}, 100);
    if (y < 0 || y >= 20) open.add_log_odds({2, y}, 2000);
  }
  EXPECT_FALSE(left_out(none.region_area(open, cluster, rule), rule));
}

TEST(PredictionAwareStrategy, SkipsPredictedFrontiersAndRanksTheRestByItsBase) {
  const PredictionAwareStrategy s(make_strategy("nearest"), 0.9);
  FrontierCluster a, b, c;
  std::vector<Candidate> cands{{&a, 1.0, 5.0, 0.95}, {&b, 4.0, 5.0, 0.5}, {&c, 2.0, 5.0, 0.2}};
  EXPECT_EQ(s.choose(cands), std::optional<std::size_t>(2));  // nearest of the unpredicted
  cands[2].predicted_share = 0.9;
  EXPECT_EQ(s.choose(cands), std::optional<std::size_t>(1));
  cands[1].predicted_share = 1.0;
  EXPECT_FALSE(s.choose(cands).has_value());                      // everything predicted: nothing left to skip to
  EXPECT_EQ(s.choose_any(cands), std::optional<std::size_t>(0));  // ... so the nearest is observed
  EXPECT_TRUE(s.uses_prediction());
  EXPECT_EQ(s.name(), "predictive");
  EXPECT_EQ(make_strategy("predictive-utility")->name(), "predictive-utility");
}

TEST(HypothesisCheck, CountsCellsTheWorldConfirms) {
  World world(100, 40, 0.05, {0, 0}, World::kFree);
  world.fill_rect({0, 1.0}, {5.0, 1.1}, World::kOccupied);  // a wall along y = 1
  slam::HypothesisMap h;
  for (double x = 0.525; x < 2.5; x += 0.05) {             // away from the world's edge (a wall)
    h.grid.add_log_odds(h.grid.cell_at(x, 1.025), 3000);   // the wall, right
    h.grid.add_log_odds(h.grid.cell_at(x, 0.525), -1000);  // free below it, right
    h.grid.add_log_odds(h.grid.cell_at(x, 1.525), 3000);   // a wall that is not there
  }
  const HypothesisCheck c = check_against_world(h, world, {}, 0.65);
  EXPECT_EQ(c.cells, 120u);
  EXPECT_EQ(c.correct, 80u);
  EXPECT_EQ(c.wall_cells, 80u);  // the two walls, of which the one at y = 1 is real
  EXPECT_EQ(c.walls_correct, 40u);
  EXPECT_NEAR(c.psi, 0.67, 0.05);  // half the predicted walls are real: 2 * 1 / (2 + 1)
}

// A right hypothesis of a room whose outer wall was not seen yet reaches past that wall; a
// built map has nothing there, the world's raster is solid. Scored over what a robot can
// observe, the free space predicted beyond the wall costs nothing; over every world cell it
// counted as missed walls.
TEST(HypothesisCheck, CellsNoRobotObservesHoldNoWalls) {
  World world(100, 40, 0.05, {0, 0}, World::kFree);         // 5 m x 2 m; beyond the raster: solid
  world.fill_rect({0, 1.8}, {5.0, 2.0}, World::kOccupied);  // the outer wall, 0.2 m thick
  slam::HypothesisMap h;
  for (double x = 0.525; x < 2.5; x += 0.05) {
    h.grid.add_log_odds(h.grid.cell_at(x, 1.775), -1000);  // free before the wall, right
    h.grid.add_log_odds(h.grid.cell_at(x, 1.825), 3000);   // the wall's face, right
    for (double y = 2.025; y < 2.5; y += 0.05) h.grid.add_log_odds(h.grid.cell_at(x, y), -1000);  // beyond
  }
  const std::vector<std::uint8_t> observable = observable_cells(world, reachable_free_area(world, {2.5, 1.0}, 0.1));
  EXPECT_EQ(observable[static_cast<std::size_t>(37 * world.width() + 50)],
            1);  // the wall's face (y 1.85)
  EXPECT_EQ(observable[static_cast<std::size_t>(39 * world.width() + 50)],
            0);  // its far side (y 1.95)
  const HypothesisCheck seen = check_against_world(h, world, observable, 0.65);
  const HypothesisCheck solid = check_against_world(h, world, {}, 0.65);
  EXPECT_GT(seen.psi, 0.9);
  EXPECT_LT(solid.psi, 0.4);  // the solid rows beyond count as walls the hypothesis missed
  EXPECT_DOUBLE_EQ(seen.psi_solid_world, solid.psi);
  EXPECT_LT(seen.world_walls, solid.world_walls);
  EXPECT_EQ(seen.predicted_walls, solid.predicted_walls);
}

// A choice reads the predicted cells still unexplored: those the robot has seen since are no
// longer in use, nor are those no robot can observe.
TEST(HypothesisCheck, ScoresThePredictionsAChoiceReads) {
  World world(100, 40, 0.05, {0, 0}, World::kFree);
  world.fill_rect({0, 1.0}, {5.0, 1.1}, World::kOccupied);  // a wall along y = 1
  slam::HypothesisMap h;
  for (double x = 0.525; x < 2.5; x += 0.05) {
    h.grid.add_log_odds(h.grid.cell_at(x, 1.025), 3000);   // the wall, right
    h.grid.add_log_odds(h.grid.cell_at(x, 0.525), -1000);  // free below it, right
    h.grid.add_log_odds(h.grid.cell_at(x, 0.325), 3000);   // a wall that is not there
  }
  PredictedMap look_ahead;
  look_ahead.add(h);
  slam::OccupancyGrid map;
  PredictionInUse before;
  score_prediction_in_use(look_ahead, map, world, {}, 0.65, before);
  EXPECT_EQ(before.cells, 120u);
  EXPECT_EQ(before.correct, 80u);
  EXPECT_EQ(before.wall_cells, 80u);
  EXPECT_EQ(before.walls_correct, 40u);
  // The robot has seen the wrong wall's row: it leaves the prediction in use.
  for (double x = 0.525; x < 2.5; x += 0.05) map.add_log_odds(map.cell_at(x, 0.325), -1000);
  PredictionInUse after = before;  // summed over choices
  score_prediction_in_use(look_ahead, map, world, {}, 0.65, after);
  EXPECT_EQ(after.cells, 200u);
  EXPECT_EQ(after.walls_correct, 80u);
  EXPECT_EQ(after.wall_cells, 120u);
  // Nothing observable: nothing in use.
  const std::vector<std::uint8_t> none(static_cast<std::size_t>(world.width() * world.height()), 0);
  PredictionInUse unobservable;
  score_prediction_in_use(look_ahead, map, world, none, 0.65, unobservable);
  EXPECT_EQ(unobservable.cells, 0u);
}

TEST(LookaheadMission, PredictiveMazeRunChecksItsHypotheses) {
  const GeneratedWorld maze = make_pslam_maze({});
  MissionOptions o = MissionOptions::defaults();
  o.pose_source = PoseSource::kTruth;
  o.strategy = "predictive";
  o.time_limit = 240;  // long enough for a few hypotheses on every code path so far
  o.harmonize();
  Mission a(maze.world, maze.start, o);
  a.run();
  ASSERT_NE(a.lookahead(), nullptr);
  const PredictionSummary s = summarize_predictions(a);
  EXPECT_GT(s.requests, 3);
  EXPECT_GT(s.hypotheses, 0);
  EXPECT_GT(s.cell_accuracy, 0.8);  // the maze is regular: most predicted cells are right
  // The predictive strategy's choices read the look-ahead map, and most of what they read is right.
  EXPECT_GT(s.in_use.cells, 0u);
  EXPECT_GT(static_cast<double>(s.in_use.correct), 0.8 * static_cast<double>(s.in_use.cells));
  // What is left predicted inside the building is a part of all that is left predicted.
  EXPECT_LE(s.final_predicted_area_inside, s.final_predicted_area + 1e-9);
  if (s.final_predicted_area_inside > 0) {
    EXPECT_GT(s.final_predicted_accuracy_inside, 0.0);
    EXPECT_LE(s.final_predicted_accuracy_inside, 1.0);
  }
  EXPECT_EQ(a.statistics().collisions, 0);
  EXPECT_EQ(static_cast<int>(a.lookahead()->records().size()), s.requests);
}

// Two targets of one selection are predicted in turn; each record names its own target and
// request time (the second request starts when the first is delivered).
TEST(LookaheadMapping, EachRecordNamesItsOwnTarget) {
  const World world(40, 40, 0.05, {0, 0}, World::kFree);
  LookaheadOptions o;
  o.enabled = true;
  LookaheadMapping la(o, world, slam::GridOptions{});
  slam::OccupancyGrid map;
  for (double y = 0.025; y < 2; y += 0.05)
    for (double x = 0.025; x < 2; x += 0.05) map.add_log_odds(map.cell_at(x, y), -1000);
  la.request(map, {{0.5, 0.5}, {1.5, 1.5}}, 0.0);
  EXPECT_EQ(la.deliver(0.5), nullptr);  // not due yet
  la.deliver(1.0);
  la.deliver(2.0);
  ASSERT_EQ(la.records().size(), 2u);
  EXPECT_DOUBLE_EQ(la.records()[0].x, 0.5);
  EXPECT_DOUBLE_EQ(la.records()[0].time, 0.0);
  EXPECT_DOUBLE_EQ(la.records()[1].x, 1.5);
  EXPECT_DOUBLE_EQ(la.records()[1].time, 1.0);
  EXPECT_EQ(la.records()[0].status, "no_control_point");  // a free square has no corner
}

TEST(LookaheadMission, OffMeansNoPredictor) {
  const GeneratedWorld maze = make_pslam_maze({});
  MissionOptions o = MissionOptions::defaults();
  o.pose_source = PoseSource::kTruth;
  o.time_limit = 5;
  o.harmonize();
  Mission m(maze.world, maze.start, o);
  m.run();
  EXPECT_EQ(m.lookahead(), nullptr);
  EXPECT_FALSE(summarize_predictions(m).enabled);
}

}  // namespace
}  // namespace lookahead::exploration
