// SPDX-License-Identifier: MIT
#include "lookahead/slam/rbpf/slam_config.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "lookahead/slam/io/parse_error.hpp"

namespace lookahead::slam {
namespace {

TEST(SlamConfig, DumpReadsBackToTheSameOptions) {
  RbpfOptions o;
  o.particles = 77;
  o.grid.resolution = 0.025;
  o.likelihood.temperature = 0.123;
  const RbpfOptions back = parse_rbpf_options(dump_rbpf_options(o), "dump");
  EXPECT_EQ(dump_rbpf_options(back), dump_rbpf_options(o));
  EXPECT_EQ(back.particles, 77);
  EXPECT_DOUBLE_EQ(back.likelihood.temperature, 0.123);
}

TEST(SlamConfig, UnknownKeyNamesFileLineAndKey) {
  try {
    parse_rbpf_options("filter:\n  particles: 10\n  partcles: 5\n", "my.yaml");
    FAIL() << "no error";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.file(), "my.yaml");
    EXPECT_EQ(e.line(), 3u);
    EXPECT_EQ(e.field(), "filter.partcles");
  }
}

TEST(SlamConfig, BadValueNamesTheValue) {
  try {
    parse_rbpf_options("grid:\n  resolution: fine\n", "my.yaml");
    FAIL() << "no error";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.line(), 2u);
    EXPECT_EQ(e.field(), "grid.resolution");
    EXPECT_EQ(e.value(), "fine");
  }
}

// The components validate their own options; the error still points at the key's line.
TEST(SlamConfig, ImpossibleValueNamesItsLineAndValue) {
  try {
    parse_rbpf_options("grid:\n  resolution: 0.05\nprediction:\n  enabled: true\n  hit_ratio_threshold: 1.5\n",
                       "my.yaml");
    FAIL() << "no error";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.file(), "my.yaml");
    EXPECT_EQ(e.line(), 5u);
    EXPECT_EQ(e.field(), "prediction.hit_ratio_threshold");
    EXPECT_EQ(e.value(), "1.5");
  }
  try {  // the motion model's own check names the key too
    parse_rbpf_options("motion:\n  srr: 0.1\n  stt: -1\n", "my.yaml");
    FAIL() << "no error";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.line(), 3u);
    EXPECT_EQ(e.field(), "motion.stt");
  }
  try {  // a bare key name in the message ("particles in 1..100000")
    parse_rbpf_options("filter:\n  seed: 3\n  particles: 0\n", "my.yaml");
    FAIL() << "no error";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.line(), 3u);
    EXPECT_EQ(e.field(), "filter.particles");
  }
}

TEST(SlamConfig, ImpossibleValueIsRejected) {
  EXPECT_THROW(parse_rbpf_options("filter:\n  particles: 0\n", "x"), ParseError);
  EXPECT_THROW(parse_rbpf_options("grid:\n  resolution: -1\n", "x"), ParseError);
  EXPECT_THROW(parse_rbpf_options("unknown_section:\n  a: 1\n", "x"), ParseError);
  // ... unless another loader reads it (the predictor's sections of a P-SLAM file).
  EXPECT_NO_THROW(parse_rbpf_options("unknown_section:\n  a: 1\n", "x", {}, {"unknown_section"}));
  EXPECT_THROW(parse_rbpf_options("[1, 2]", "x"), ParseError);
  EXPECT_THROW(parse_rbpf_options("filter: {particles: [", "x"), ParseError);
}

TEST(SlamConfig, LeftOutKeysKeepTheirDefaults) {
  const RbpfOptions o = parse_rbpf_options("motion:\n  srr: 0.3\n", "x");
  EXPECT_DOUBLE_EQ(o.motion.srr, 0.3);
  EXPECT_DOUBLE_EQ(o.motion.stt, MotionModelOptions{}.stt);
  EXPECT_EQ(o.particles, RbpfOptions{}.particles);
}

}  // namespace
}  // namespace lookahead::slam
