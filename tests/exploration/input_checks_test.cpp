// SPDX-License-Identifier: MIT
// Bad worlds, starts and studies end with errors naming the file, field and value.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "lookahead/exploration/study_config.hpp"
#include "lookahead/exploration/world_loader.hpp"
#include "lookahead/exploration/world_source.hpp"
#include "lookahead/slam/io/parse_error.hpp"
#include "temp_file.hpp"

namespace lookahead::exploration {
namespace {

using slam::ParseError;
using slam::test::TempPath;

// A 20 x 20 PGM, walls on its border.
void write_box(const std::string& path) {
  std::ofstream out(path, std::ios::binary);
  out << "P5\n20 20\n255\n";
  for (int y = 0; y < 20; ++y)
    for (int x = 0; x < 20; ++x) out.put(static_cast<char>(x == 0 || y == 0 || x == 19 || y == 19 ? 0 : 255));
}

std::string error_of(const WorldSpec& spec) {
  try {
    (void)load_world(spec, 0.1);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

TEST(InputChecks, DeeplyNestedStageWorldIsAParseErrorNotAStackOverflow) {
  TempPath f(".world");
  std::string text;
  for (int i = 0; i < 100000; ++i) text += "m (\n";
  f.write(text);
  try {
    (void)load_stage_world(f.str());
    FAIL() << "no error";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.field(), "nesting depth");
    EXPECT_EQ(e.line(), 65u);
  }
}

TEST(InputChecks, ImageWorldNeedsItsResolutionStated) {
  TempPath dir;
  std::filesystem::create_directory(dir.str());
  WorldSpec spec;
  spec.name = dir.str() + "/box.pgm";
  write_box(spec.name);
  EXPECT_NE(error_of(spec).find("resolution (m/pixel) of an image world must be stated"), std::string::npos)
      << error_of(spec);
  spec.image_resolution = 0.1;
  EXPECT_EQ(error_of(spec), "");
}

TEST(InputChecks, StartOutsideTheMapAndInCollisionAreToldApart) {
  TempPath dir;
  std::filesystem::create_directory(dir.str());
  WorldSpec spec;
  spec.name = dir.str() + "/box.pgm";
  spec.image_resolution = 0.1;
  write_box(spec.name);
  spec.start = slam::Pose2{50.0, 1.0, 0.0};
  const std::string outside = error_of(spec);
  EXPECT_NE(outside.find("is outside the map"), std::string::npos) << outside;
  EXPECT_NE(outside.find("box.pgm"), std::string::npos) << outside;
  EXPECT_NE(outside.find("50.0"), std::string::npos) << outside;
  spec.start = slam::Pose2{0.05, 1.0, 0.0};
  const std::string wall = error_of(spec);
  EXPECT_NE(wall.find("is in collision"), std::string::npos) << wall;
  EXPECT_NE(wall.find("box.pgm"), std::string::npos) << wall;
}

TEST(InputChecks, StudyLimitsAndImageResolution) {
  const std::string tail = "strategies: [nearest]\n";
  try {
    (void)parse_study("name: s\nworlds:\n  - {name: a.png}\n" + tail + "seeds: [1]\n", "study.yaml", "/d");
    FAIL() << "no error";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.field(), "worlds.resolution");
    EXPECT_EQ(e.line(), 3u);
  }
  try {
    (void)parse_study("name: s\nworlds:\n  - {name: office}\n" + tail + "seeds: {from: 1, count: 1000000}\n",
                      "study.yaml", "/d");
    FAIL() << "no error";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.field(), "seeds.count");
    EXPECT_EQ(e.value(), "1000000");
  }
}

}  // namespace
}  // namespace lookahead::exploration
