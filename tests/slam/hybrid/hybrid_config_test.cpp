// SPDX-License-Identifier: MIT
#include "lookahead/slam/hybrid/hybrid_config.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "lookahead/slam/io/parse_error.hpp"

namespace lookahead::slam::hybrid {
namespace {

TEST(HybridConfig, DumpReadsBackToTheSameOptions) {
  HybridConfig c;
  c.filter.fastslam.particles = 123;
  c.study.alphas = {0.9, 0.5};
  c.study.betas = {0.01, 0.03};
  const HybridConfig back = parse_hybrid_config(dump_hybrid_config(c), "dump");
  EXPECT_EQ(dump_hybrid_config(back), dump_hybrid_config(c));
  EXPECT_EQ(back.filter.fastslam.particles, 123);
  EXPECT_EQ(back.study.alphas, (std::vector<double>{0.9, 0.5}));
}

TEST(HybridConfig, ShippedDefaultsMatchTheCode) {
  std::ifstream in(std::string(LOOKAHEAD_SOURCE_DIR) + "/config/hybrid/default.yaml");
  ASSERT_TRUE(in) << "config/hybrid/default.yaml missing";
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), "# lookahead hybrid defaults (lookahead config dump hybrid)\n" + dump_hybrid_config({}))
      << "regenerate with: lookahead config dump hybrid > config/hybrid/default.yaml";
}

// `slam --method hybrid --config config/hybrid/default.yaml` used to replace the log-mode
// defaults (100 particles, alpha 0.5, beta 0.1) with the simulation's values: a log
// config with simulation sections is refused at the section's line; a log config that
// gives only the keys to change keeps the log-mode defaults for the rest.
TEST(HybridConfig, LogConfigRefusesTheSimulationFileAndKeepsLogDefaults) {
  const std::string dir = std::string(LOOKAHEAD_SOURCE_DIR) + "/config/hybrid/";
  HybridConfig log_base;
  log_base.filter.fastslam.particles = 100;
  log_base.filter.existence.alpha = 0.5;
  log_base.filter.existence.beta = 0.1;
  try {
    load_hybrid_log_config(dir + "default.yaml", log_base);
    FAIL() << "the simulation defaults were accepted on a log";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.file(), dir + "default.yaml");
    EXPECT_EQ(e.field(), "simulation");
    EXPECT_GT(e.line(), 30u);
  }
  const HybridConfig csail = load_hybrid_log_config(dir + "csail.yaml", log_base);
  EXPECT_EQ(csail.filter.fastslam.particles, 100);
  EXPECT_DOUBLE_EQ(csail.filter.existence.alpha, 0.5);
  EXPECT_DOUBLE_EQ(csail.scan_landmarks.split_tolerance, 0.12);
  EXPECT_TRUE(log_base.filter.fusion.relinearise);  // the default back-end re-solves ...
  EXPECT_FALSE(csail.filter.fusion.relinearise);    // ... csail.yaml keeps the EKF (README)
}

TEST(HybridConfig, BadInputNamesFileLineKeyAndValue) {
  try {
    parse_hybrid_config("fusion:\n  period: 10\n  perod: 5\n", "h.yaml");
    FAIL() << "no error";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.file(), "h.yaml");
    EXPECT_EQ(e.line(), 3u);
    EXPECT_EQ(e.field(), "fusion.perod");
  }
  try {
    parse_hybrid_config("fastslam:\n  particles: many\n", "h.yaml");
    FAIL() << "no error";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.line(), 2u);
    EXPECT_EQ(e.value(), "many");
  }
  EXPECT_THROW(parse_hybrid_config("existence:\n  alpha: 1.5\n", "h.yaml"), ParseError);
  EXPECT_THROW(parse_hybrid_config("study:\n  alphas: [1.0]\n  betas: [0.0, 0.1]\n", "h.yaml"), ParseError);
  EXPECT_THROW(parse_hybrid_config("scan_landmarks:\n  min_points: 1\n", "h.yaml"), ParseError);
  EXPECT_THROW(parse_hybrid_config("scan_landmarks:\n  corner_min_angle: 2.0\n", "h.yaml"), ParseError);
  try {
    parse_hybrid_config("scan_landmarks:\n  split_tolerance: 0.05\n  min_lenght: 1\n", "h.yaml");
    FAIL() << "no error";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.line(), 3u);
    EXPECT_EQ(e.field(), "scan_landmarks.min_lenght");
  }
}

TEST(HybridConfig, ScanLandmarkOptionsAreRead) {
  const HybridConfig c = parse_hybrid_config(
      "scan_landmarks:\n  max_range: 12\n  min_points: 5\n  line_ends: false\n  corner_sigma: 0.08\n", "h.yaml");
  EXPECT_DOUBLE_EQ(c.scan_landmarks.max_range, 12.0);
  EXPECT_EQ(c.scan_landmarks.min_points, 5);
  EXPECT_FALSE(c.scan_landmarks.line_ends);
  EXPECT_DOUBLE_EQ(c.scan_landmarks.corner_sigma, 0.08);
  EXPECT_DOUBLE_EQ(c.scan_landmarks.split_tolerance, ScanLandmarkOptions{}.split_tolerance);  // untouched
}

}  // namespace
}  // namespace lookahead::slam::hybrid
