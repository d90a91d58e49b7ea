// SPDX-License-Identifier: MIT
// Loaders on hand-made files: orientation, pixel rules, and errors that name file and line.
#include "lookahead/exploration/world_loader.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "lookahead/slam/io/parse_error.hpp"
#include "temp_file.hpp"

namespace lookahead::exploration {
namespace {

using slam::ParseError;
using slam::test::TempPath;

// A 4 x 3 binary PGM: top-left pixel black (wall), one 205 (map_server unknown), rest 254.
void write_pgm(const std::string& path) {
  std::ofstream out(path, std::ios::binary);
  out << "P5\n4 3\n255\n";
  const unsigned char px[12] = {0, 254, 254, 254, 254, 205, 254, 254, 254, 254, 254, 254};
  out.write(reinterpret_cast<const char*>(px), 12);
}

TEST(WorldLoader, ImageTopRowIsTheWorldsTopRow) {
  TempPath dir;
  std::filesystem::create_directory(dir.str());
  write_pgm(dir.str() + "/m.pgm");
  const World w = load_image_world(dir.str() + "/m.pgm", {0.5, {1.0, 2.0}, PixelRule::stage()});
  EXPECT_EQ(w.width(), 4);
  EXPECT_EQ(w.height(), 3);
  EXPECT_TRUE(w.is_occupied(slam::CellIndex{0, 2}));   // image (row 0, col 0)
  EXPECT_FALSE(w.is_occupied(slam::CellIndex{1, 1}));  // 205 > 127: free for Stage
  EXPECT_TRUE(w.is_occupied(1.0 + 0.25, 2.0 + 1.25));  // metric centre of cell (0, 2)
  EXPECT_TRUE(w.is_occupied(0.9, 2.1));                // outside counts as occupied
  EXPECT_EQ(w.free_cell_count(), 11u);
}

TEST(WorldLoader, MapServerUnknownIsOccupied) {
  TempPath dir;
  std::filesystem::create_directory(dir.str());
  write_pgm(dir.str() + "/m.pgm");
  std::ofstream(dir.str() + "/m.yaml") << "image: m.pgm\nresolution: 0.1\norigin: [-1.0, -2.0, 0.0]\n"
                                          "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n";
  const World w = load_map_yaml(dir.str() + "/m.yaml");
  EXPECT_TRUE(w.is_occupied(slam::CellIndex{1, 1}));  // 205 -> p = 0.196, not < free_thresh
  EXPECT_FALSE(w.is_occupied(slam::CellIndex{2, 1}));
  EXPECT_DOUBLE_EQ(w.origin().x(), -1.0);
  EXPECT_EQ(w.free_cell_count(), 10u);
  std::ofstream(dir.str() + "/n.yaml") << "image: m.pgm\nresolution: 0.1\norigin: [0, 0, 0]\nnegate: 1\n";
  EXPECT_EQ(load_map_yaml(dir.str() + "/n.yaml").free_cell_count(), 1u);  // only the black pixel
}

template <typename F>
ParseError expect_parse_error(F&& f) {
  try {
    f();
  } catch (const ParseError& e) {
    return e;
  }
  ADD_FAILURE() << "no ParseError";
  return ParseError("", 0, "", "", "");
}

TEST(WorldLoader, BadYamlNamesFileLineKeyAndValue) {
  TempPath dir;
  std::filesystem::create_directory(dir.str());
  write_pgm(dir.str() + "/m.pgm");
  const std::string y = dir.str() + "/bad.yaml";
  std::ofstream(y) << "image: m.pgm\nresolution: -0.5\norigin: [0, 0, 0]\n";
  ParseError e = expect_parse_error([&] { (void)load_map_yaml(y); });
  EXPECT_EQ(e.file(), y);
  EXPECT_EQ(e.line(), 2u);
  EXPECT_EQ(e.field(), "resolution");
  EXPECT_EQ(e.value(), "-0.5");
  std::ofstream(y) << "image: m.pgm\nresolution: 0.05\norigin: [0, 0, 0]\ncolour: red\n";
  e = expect_parse_error([&] { (void)load_map_yaml(y); });
  EXPECT_EQ(e.line(), 4u);
  EXPECT_EQ(e.field(), "colour");
  std::ofstream(y) << "image: missing.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n";
  e = expect_parse_error([&] { (void)load_map_yaml(y); });
  EXPECT_EQ(e.line(), 1u);
  EXPECT_EQ(e.field(), "image");
  std::ofstream(y) << "image: m.pgm\nresolution: 0.05\norigin: [0, 0, 0.5]\n";
  EXPECT_EQ(expect_parse_error([&] { (void)load_map_yaml(y); }).field(), "origin");
  std::ofstream(y) << "image: m.pgm\nresolution: 0.05\norigin: [0, 0, 0]\nmode: raw\n";
  e = expect_parse_error([&] { (void)load_map_yaml(y); });
  EXPECT_EQ(e.line(), 4u);
  EXPECT_EQ(e.value(), "raw");
  std::ofstream(y) << "image: m.pgm\nresolution: [0.05\n";
  EXPECT_GT(expect_parse_error([&] { (void)load_map_yaml(y); }).line(), 0u);
}

TEST(WorldLoader, StageWorldWithDefinesAndStage2Syntax) {
  TempPath dir;
  std::filesystem::create_directory(dir.str());
  write_pgm(dir.str() + "/m.pgm");
  const std::string f = dir.str() + "/a.world";
  // `define` inheritance (maze.world style) and an indexed key (roomba block style).
  std::ofstream(f) << "# comment\ndefine plan floorplan ( boundary 1 point[0] [ 1 2 ] )\n"
                      "plan\n(\n  bitmap \"m.pgm\" # the map\n  size [2.0 1.5 0.5]\n"
                      "  pose [ 10 20 0 180 ]\n)\n";
  const World w = load_stage_world(f);
  EXPECT_NEAR(w.resolution(), 0.5, 1e-12);
  EXPECT_NEAR(w.origin().x(), 9.0, 1e-12);
  EXPECT_NEAR(w.origin().y(), 19.25, 1e-12);
  EXPECT_TRUE(w.is_occupied(slam::CellIndex{3, 0}));  // top-left pixel, turned half a circle
  std::ofstream(f) << "map(\n bitmap \"m.pgm\"\n bitmap_resolution 0.25\n)\n";
  EXPECT_NEAR(load_stage_world(f).width_m(), 1.0, 1e-12);
}

TEST(WorldLoader, BadStageWorldNamesFileLineKeyAndValue) {
  TempPath dir;
  std::filesystem::create_directory(dir.str());
  write_pgm(dir.str() + "/m.pgm");
  const std::string f = dir.str() + "/bad.world";
  std::ofstream(f) << "resolution 0.02\n\nfloorplan\n(\n  bitmap \"m.pgm\"\n  size [abc 5]\n)\n";
  ParseError e = expect_parse_error([&] { (void)load_stage_world(f); });
  EXPECT_EQ(e.file(), f);
  EXPECT_EQ(e.line(), 6u);
  EXPECT_EQ(e.field(), "size");
  EXPECT_EQ(e.value(), "abc 5");
  std::ofstream(f) << "floorplan\n(\n  bitmap \"nothere.png\"\n  size [1 1]\n)\n";
  e = expect_parse_error([&] { (void)load_stage_world(f); });
  EXPECT_EQ(e.line(), 3u);
  EXPECT_EQ(e.field(), "bitmap");
  EXPECT_EQ(e.value(), "nothere.png");
  std::ofstream(f) << "floorplan\n(\n  bitmap \"m.pgm\n)\n";
  EXPECT_EQ(expect_parse_error([&] { (void)load_stage_world(f); }).line(), 3u);
  std::ofstream(f) << "floorplan ( bitmap \"m.pgm\" size [1 1] pose [0 0 0 45] )\n";
  EXPECT_EQ(expect_parse_error([&] { (void)load_stage_world(f); }).field(), "pose");
  std::ofstream(f) << "window ( size [ 1 2 ] )\n";
  EXPECT_EQ(expect_parse_error([&] { (void)load_stage_world(f); }).field(), "floorplan");
  std::ofstream(f) << "floorplan ( bitmap \"m.pgm\"\n";
  EXPECT_EQ(expect_parse_error([&] { (void)load_stage_world(f); }).line(), 1u);
}

}  // namespace
}  // namespace lookahead::exploration
