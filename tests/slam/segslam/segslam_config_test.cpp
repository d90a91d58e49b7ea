// SPDX-License-Identifier: MIT
#include "lookahead/slam/segslam/segslam_config.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "lookahead/slam/io/parse_error.hpp"

namespace lookahead::slam {
namespace {

TEST(SegSlamConfig, ShippedDefaultsMatchTheCode) {
  std::ifstream in(std::string(LOOKAHEAD_SOURCE_DIR) + "/config/segslam/default.yaml");
  ASSERT_TRUE(in) << "config/segslam/default.yaml missing";
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), "# lookahead segslam defaults (lookahead config dump segslam)\n" + dump_segslam_options({}));
}

TEST(SegSlamConfig, DumpReadsBack) {
  segslam::SegSlamOptions o;
  o.matching.icp_sigma = 0.123;
  o.segmentation.min_segment_updates = 7;
  const auto back = parse_segslam_options(dump_segslam_options(o), "dump");
  EXPECT_EQ(dump_segslam_options(back), dump_segslam_options(o));
}

// The shared-search switch reads back, and a value that is not a boolean is named with its line.
TEST(SegSlamConfig, ShareBySegmentReadsAndRejectsNonBooleans) {
  EXPECT_FALSE(parse_segslam_options("matching:\n  share_by_segment: false\n", "s.yaml").matching.share_by_segment);
  try {
    parse_segslam_options("matching:\n  icp_sigma: 0.1\n  share_by_segment: maybe\n", "s.yaml");
    FAIL() << "no error";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.file(), "s.yaml");
    EXPECT_EQ(e.line(), 3u);
    EXPECT_EQ(e.field(), "matching.share_by_segment");
    EXPECT_NE(std::string(e.what()).find("maybe"), std::string::npos) << e.what();
  }
}

TEST(SegSlamConfig, ParticleChainReadsAndRejectsNonBooleans) {
  EXPECT_TRUE(parse_segslam_options("", "s.yaml").offline.particle_chain);
  EXPECT_FALSE(parse_segslam_options("offline:\n  particle_chain: false\n", "s.yaml").offline.particle_chain);
  try {
    parse_segslam_options("offline:\n  map_samples: 3\n  particle_chain: 2\n", "s.yaml");
    FAIL() << "no error";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.line(), 3u);
    EXPECT_EQ(e.field(), "offline.particle_chain");
    EXPECT_EQ(e.value(), "2");
  }
  // No map samples: allowed only when the chain is a candidate (it is then the map).
  EXPECT_EQ(parse_segslam_options("offline:\n  map_samples: 0\n", "s.yaml").offline.map_samples, 0);
  EXPECT_THROW(parse_segslam_options("offline:\n  map_samples: 0\n  particle_chain: false\n", "s.yaml"), ParseError);
}

TEST(SegSlamConfig, ErrorsNameFileLineKeyAndValue) {
  try {
    parse_segslam_options("matching:\n  icp_sigma: 0.1\n  icp_sigm: 1\n", "s.yaml");
    FAIL() << "no error";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.file(), "s.yaml");
    EXPECT_EQ(e.line(), 3u);
    EXPECT_EQ(e.field(), "matching.icp_sigm");
  }
  try {
    parse_segslam_options("segmentation:\n  lookahead_s: soon\n", "s.yaml");
    FAIL() << "no error";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.line(), 2u);
    EXPECT_EQ(e.value(), "soon");
  }
  EXPECT_THROW(parse_segslam_options("segmentation:\n  lookahead_s: -1\n", "s.yaml"), ParseError);
  try {
    parse_segslam_options("matching:\n  search_radius: 2\n  max_search_radius: -3\n", "s.yaml");
    FAIL() << "no error";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.file(), "s.yaml");
    EXPECT_EQ(e.line(), 3u);
    EXPECT_EQ(e.field(), "matching.max_search_radius");
    EXPECT_EQ(e.value(), "-3");
  }
  EXPECT_THROW(parse_segslam_options("filter:\n  particles: 3\n", "s.yaml"), ParseError);
  try {  // a retired key is an unknown key
    parse_segslam_options("matching:\n  icp_sigma: 0.05\n  confirmed_boost: 10\n", "s.yaml");
    FAIL() << "no error";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.line(), 3u);
    EXPECT_EQ(e.field(), "matching.confirmed_boost");
  }
}

}  // namespace
}  // namespace lookahead::slam
