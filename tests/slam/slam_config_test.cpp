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

// proposal.kind is a named choice: read and dumped by name, and a wrong name gets an error
// that lists the allowed ones.
TEST(SlamConfig, ProposalKindIsANamedChoice) {
  const RbpfOptions o = parse_rbpf_options("proposal:\n  kind: motion_model\n", "my.yaml");
  EXPECT_EQ(o.proposal.kind, ProposalKind::kMotionModel);
  EXPECT_EQ(RbpfOptions{}.proposal.kind, ProposalKind::kScanMatch);
  EXPECT_NE(dump_rbpf_options(o).find("  kind: motion_model  #"), std::string::npos);
  EXPECT_NE(dump_rbpf_options({}).find("  kind: scan_match  #"), std::string::npos);
  EXPECT_EQ(parse_rbpf_options(dump_rbpf_options(o), "dump").proposal.kind, ProposalKind::kMotionModel);
  try {
    parse_rbpf_options("proposal:\n  kernel_linear: 0.025\n  kind: standard\n", "my.yaml");
    FAIL() << "no error";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.file(), "my.yaml");
    EXPECT_EQ(e.line(), 3u);
    EXPECT_EQ(e.field(), "proposal.kind");
    EXPECT_EQ(e.value(), "standard");
    EXPECT_NE(std::string(e.what()).find("scan_match | motion_model"), std::string::npos) << e.what();
  }
  for (const char* bad : {"proposal:\n  kind: [scan_match]\n", "proposal:\n  kind: 1\n", "proposal:\n  kind:\n"}) {
    EXPECT_THROW(parse_rbpf_options(bad, "my.yaml"), ParseError) << bad;
  }
}

// A hit ratio above 1 is no way to switch the scan matcher off: proposal.kind is.
TEST(SlamConfig, HitRatioAboveOneIsRejected) {
  try {
    parse_rbpf_options("matcher:\n  min_hit_ratio: 1.1\n", "my.yaml");
    FAIL() << "no error";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.line(), 2u);
    EXPECT_EQ(e.field(), "matcher.min_hit_ratio");
    EXPECT_EQ(e.value(), "1.1");
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
