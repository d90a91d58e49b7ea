// SPDX-License-Identifier: MIT
#include "lookahead/slam/limits/input_limits.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <stdexcept>

#include "lookahead/slam/grid/occupancy_grid.hpp"
#include "lookahead/slam/io/image_header.hpp"
#include "lookahead/slam/io/map_io.hpp"
#include "lookahead/slam/io/parse_error.hpp"
#include "lookahead/slam/parallel/parallel_errors.hpp"
#include "lookahead/slam/rbpf/rbpf.hpp"
#include "lookahead/slam/rbpf/slam_config.hpp"
#include "temp_file.hpp"

namespace lookahead::slam {
namespace {

TEST(ParallelErrors, ExceptionInAParallelLoopReachesTheCaller) {
  ParallelErrors errors;
  int ran = 0;
#pragma omp parallel for num_threads(2) reduction(+ : ran)
  for (int i = 0; i < 100; ++i) {
    errors.run([&] {
      ++ran;
      if (i == 7) throw std::length_error("seven");
    });
  }
  EXPECT_TRUE(errors.failed());
  EXPECT_LE(ran, 100);
  EXPECT_THROW(errors.rethrow(), std::length_error);
}

TEST(ParallelErrors, NoExceptionNoRethrow) {
  ParallelErrors errors;
  errors.run([] {});
  EXPECT_FALSE(errors.failed());
  EXPECT_NO_THROW(errors.rethrow());
}

TEST(InputLimits, AGridFarOffTheMapIsRefusedWithItsExtent) {
  OccupancyGrid grid(GridOptions{});
  grid.add_log_odds(grid.cell_at(0.0, 0.0), grid.fixed_hit());
  try {
    grid.add_log_odds(grid.cell_at(1e6, 1e6), grid.fixed_hit());  // 1000 km away
    FAIL() << "no error";
  } catch (const limits::ResourceLimitError& e) {
    EXPECT_NE(std::string(e.what()).find("kMaxGridTiles"), std::string::npos) << e.what();
  }
  EXPECT_THROW(grid.add_log_odds(grid.cell_at(NAN, 0.0), grid.fixed_hit()), limits::ResourceLimitError);
}

TEST(InputLimits, HugeMotionNoiseInASlamYamlIsAConfigError) {
  try {
    (void)parse_rbpf_options("motion:\n  srr: 1e12\n", "slam.yaml");
    FAIL() << "no error";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("srr"), std::string::npos) << e.what();
  }
  EXPECT_ANY_THROW((void)parse_rbpf_options("likelihood:\n  max_range: 1e9\n", "slam.yaml"));
}

TEST(InputLimits, ParticlesBeyondTheMachinesMemoryAreRefusedUpFront) {
  RbpfOptions o;
  o.particles = 100000;
  Rbpf filter(o);
  LaserScan s;
  s.angle_min = -M_PI;
  s.angle_increment = 2 * M_PI / 360;
  s.max_range = 80;
  s.ranges.assign(360, 60.0f);  // a 60 m circle: ~900 tiles
  const std::uint64_t need = 100000ull * 900 * sizeof(GridTile);
  if (need < limits::available_memory_bytes()) GTEST_SKIP() << "this machine has over " << need << " bytes";
  try {
    filter.add_scan(s);
    FAIL() << "no error";
  } catch (const limits::ResourceLimitError& e) {
    EXPECT_NE(std::string(e.what()).find("100000 particles"), std::string::npos) << e.what();
  }
}

TEST(InputLimits, PgmWithAbsurdDimensionsIsAParseErrorNotAnOpenCvException) {
  test::TempPath pgm(".pgm");
  pgm.write("P5\n2000000000 2000000000\n255\n\x01\x02");
  test::TempPath yaml(".yaml");
  yaml.write("image: " + pgm.str() + "\nresolution: 0.05\norigin: [0, 0, 0]\n");
  try {
    (void)read_map(yaml.str());
    FAIL() << "no error";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.field(), "image");
    EXPECT_EQ(e.value(), "2000000000 x 2000000000");
  }
  pgm.write("P5\n# comment\n99999999999999999999 1\n255\n");
  EXPECT_THROW((void)read_map(yaml.str()), ParseError);
}

}  // namespace
}  // namespace lookahead::slam
