// SPDX-License-Identifier: MIT
#include "lookahead/pipeline/pslam_config.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "../slam/temp_file.hpp"
#include "lookahead/pipeline/log_prediction_config.hpp"
#include "lookahead/slam/io/parse_error.hpp"
#include "lookahead/slam/rbpf/slam_config.hpp"

namespace lookahead::pipeline {
namespace {

// config/slam/default.yaml documents the defaults: it must say exactly what the code does.
TEST(PslamConfig, ShippedDefaultsMatchTheCode) {
  std::ifstream in(std::string(LOOKAHEAD_SOURCE_DIR) + "/config/slam/default.yaml");
  ASSERT_TRUE(in) << "config/slam/default.yaml missing";
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), dump_pslam_options({}))
      << "regenerate with: lookahead config dump slam > config/slam/default.yaml";
  const PslamOptions shipped = load_pslam_options(std::string(LOOKAHEAD_SOURCE_DIR) + "/config/slam/default.yaml");
  EXPECT_EQ(dump_pslam_options(shipped), dump_pslam_options({}));
}

// A live robot never waits for a prediction: one key changes the waiting only.
TEST(PslamConfig, LiveSettingOnlyStopsWaiting) {
  const slam::test::TempPath file(".yaml");
  file.write("log_targets:\n  wait_for_predictions: false\n");
  const PslamOptions live = load_pslam_options(file.str());
  EXPECT_FALSE(live.prediction.targets.wait_for_predictions);
  PslamOptions expected;
  expected.prediction.targets.wait_for_predictions = false;
  EXPECT_EQ(dump_pslam_options(live), dump_pslam_options(expected));
}

TEST(PslamConfig, DumpReadsBackToTheSameOptions) {
  LogPredictionOptions o;
  o.predictor.similarity_threshold = 0.7;
  o.predictor.max_conflict_share = 0.25;
  o.targets.wait_for_predictions = false;
  o.targets.period_updates = 3;
  const LogPredictionOptions back = parse_log_prediction_options(dump_log_prediction_options(o), "dump");
  EXPECT_EQ(dump_log_prediction_options(back), dump_log_prediction_options(o));
  EXPECT_DOUBLE_EQ(back.predictor.similarity_threshold, 0.7);
  EXPECT_FALSE(back.targets.wait_for_predictions);
}

TEST(PslamConfig, OneFileFeedsBothLoaders) {
  const std::string text =
      "filter:\n  particles: 12\npredictor:\n  similarity_threshold: 0.7\n"
      "log_targets:\n  wait_for_predictions: false\n";
  const slam::RbpfOptions rbpf = slam::parse_rbpf_options(text, "f.yaml", {}, log_prediction_section_names());
  const LogPredictionOptions p = parse_log_prediction_options(text, "f.yaml", {}, slam::rbpf_section_names());
  EXPECT_EQ(rbpf.particles, 12);
  EXPECT_DOUBLE_EQ(p.predictor.similarity_threshold, 0.7);
  EXPECT_FALSE(p.targets.wait_for_predictions);
  // Each loader still rejects what neither reads.
  EXPECT_THROW(parse_log_prediction_options(text + "predicter:\n  a: 1\n", "f.yaml", {}, slam::rbpf_section_names()),
               slam::ParseError);
}

TEST(PslamConfig, UnknownKeyNamesFileLineAndKey) {
  try {
    parse_log_prediction_options("predictor:\n  control_point_range: 5\n  similarity_treshold: 0.7\n", "my.yaml");
    FAIL() << "no error";
  } catch (const slam::ParseError& e) {
    EXPECT_EQ(e.file(), "my.yaml");
    EXPECT_EQ(e.line(), 3u);
    EXPECT_EQ(e.field(), "predictor.similarity_treshold");
  }
}

TEST(PslamConfig, BadAndImpossibleValuesAreRejected) {
  try {
    parse_log_prediction_options("log_targets:\n  wait_for_predictions: maybe\n", "my.yaml");
    FAIL() << "no error";
  } catch (const slam::ParseError& e) {
    EXPECT_EQ(e.line(), 2u);
    EXPECT_EQ(e.field(), "log_targets.wait_for_predictions");
    EXPECT_EQ(e.value(), "maybe");
  }
  // The paper allows thresholds of 0.4..0.7 only (sec. III-C).
  try {
    parse_log_prediction_options("predictor:\n  similarity_threshold: 0.9\n", "my.yaml");
    FAIL() << "no error";
  } catch (const slam::ParseError& e) {
    EXPECT_NE(std::string(e.what()).find("similarity_threshold"), std::string::npos) << e.what();
    EXPECT_EQ(e.line(), 2u);
    EXPECT_EQ(e.value(), "0.9");
  }
  EXPECT_THROW(parse_log_prediction_options("log_targets:\n  period_updates: 0\n", "x"), slam::ParseError);
  EXPECT_THROW(parse_log_prediction_options("log_targets:\n  range: -1\n", "x"), slam::ParseError);
}

}  // namespace
}  // namespace lookahead::pipeline
