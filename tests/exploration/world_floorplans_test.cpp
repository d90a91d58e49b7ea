// SPDX-License-Identifier: MIT
// Every floor plan in shared/data/floorplans loads with the size its index documents. The
// recipe per map (which loader, resolution, pixel rule) comes from maps_index.csv's
// resolution_source and pixel_meaning columns and kth/SOURCES.md section 1; a map added to
// an index without a recipe here fails the test.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "lookahead/exploration/world_loader.hpp"

namespace lookahead::exploration {
namespace {

namespace fs = std::filesystem;
const fs::path kPlans = fs::path(LOOKAHEAD_SHARED_DIR) / "data" / "floorplans";

std::vector<std::string> split_csv(const std::string& line) {
  std::vector<std::string> out(1);
  bool quoted = false;
  for (const char c : line) {
    if (c == '"')
      quoted = !quoted;
    else if (c == ',' && !quoted)
      out.emplace_back();
    else
      out.back() += c;
  }
  return out;
}

std::vector<std::map<std::string, std::string>> read_csv(const fs::path& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  const auto header = split_csv(line);
  std::vector<std::map<std::string, std::string>> rows;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    const auto cells = split_csv(line);
    std::map<std::string, std::string> row;
    for (std::size_t i = 0; i < header.size() && i < cells.size(); ++i) row[header[i]] = cells[i];
    rows.push_back(row);
  }
  return rows;
}

// How each maps_index.csv row loads, following its resolution_source and pixel_meaning.
World load_indexed(const std::string& file) {
  const PixelRule map_server = PixelRule::map_server(0.196, false);  // ROS defaults
  const PixelRule below_250{249.0, false, PixelChannel::kMean};
  const std::map<std::string, std::pair<std::string, StageWorldOptions>> stage = {
      {"stage/hospital_section.png", {"stage/worlds/everything.world", {}}},
      {"stage/hospital.png", {"stage/worlds/hospital.world", {}}},
      {"stage/cave.png", {"stage/worlds/simple.world", {}}},
      {"stage/autolab.png", {"stage/worlds/autolab.world", {}}},
      {"stage/uoa_robotics_lab.png", {"stage/worlds/uoa_robotics_lab.world", {}}},
      {"stage/sal2.png", {"stage/worlds/test_2008_sal2.world", {below_250, 0.0}}},
      {"ros_navigation_tutorials/willow-full.pgm",
       {"ros_navigation_tutorials/worlds/willow-pr2.world", {map_server, 0.0}}},
      {"ros_navigation_tutorials/willow-full-0.05.pgm",
       {"ros_navigation_tutorials/worlds/willow-pr2-5cm.world", {map_server, 0.0}}},
  };
  if (auto it = stage.find(file); it != stage.end()) {
    return load_stage_world((kPlans / it->second.first).string(), it->second.second);
  }
  for (const char* yaml : {"ros_navigation_tutorials/lse_arena", "turtlebot_simulator/maze",
                           "turtlebot_simulator/robocup", "turtlebot_simulator/sparse_obstacles"}) {
    if (file.rfind(yaml, 0) == 0) return load_map_yaml((kPlans / (std::string(yaml) + ".yaml")).string());
  }
  ImageWorldOptions o;
  if (file == "stage/simple_rooms.png") {
    o.resolution = 0.05;  // turtlebot_stdr's simple_rooms.yaml; Stage's pixel rule
  } else if (file == "stage/SRI-AIC-kwing.png") {
    o.resolution = 0.1;  // no resolution upstream: the test only needs some positive value
    o.rule = below_250;  // 0 wall, 128 unknown (occupied for the truth), 255 free
  } else if (file.rfind("mrgs_compression_benchmark/", 0) == 0) {
    o.resolution = 0.05;  // assumed upstream (gmapping default); 0/205/254 map_saver values
    o.rule = map_server;
  } else {
    ADD_FAILURE() << "no recipe for " << file;
    return World(1, 1, 1.0, {0, 0});
  }
  return load_image_world((kPlans / file).string(), o);
}

TEST(WorldLoader, LoadsEveryFloorPlanInTheIndex) {
  const auto rows = read_csv(kPlans / "maps_index.csv");
  ASSERT_EQ(rows.size(), 17u);
  for (const auto& row : rows) {
    SCOPED_TRACE(row.at("file"));
    const World w = load_indexed(row.at("file"));
    const double free_fraction = static_cast<double>(w.free_cell_count()) / w.cells().size();
    EXPECT_GT(free_fraction, 0.05);
    EXPECT_LT(free_fraction, 0.99);           // Stage line drawings are free outside the walls too
    if (row.at("width_m").empty()) continue;  // SRI K-wing: no size known
    // Willow and the LSE arena are turned 90 deg by their .world pose: compare unordered.
    std::vector<double> got{w.width_m(), w.height_m()};
    std::vector<double> want{std::stod(row.at("width_m")), std::stod(row.at("height_m"))};
    std::sort(got.begin(), got.end());
    std::sort(want.begin(), want.end());
    for (int i = 0; i < 2; ++i) EXPECT_NEAR(got[i], want[i], 0.01 * want[i] + w.resolution());
  }
}

TEST(WorldLoader, StagePoseRotatesAndCentresTheBitmap) {
  // willow-pr2.world: size [58.4 52.6], pose [-26.3 29.2 0 90]: turned a quarter, the map
  // spans x in [-52.6, 0] and y in [0, 58.4]. Upstream agrees: navigation_stage's AMCL starts
  // at (47.48, 21.65, -1.0) in the unturned map_server frame, which is the 5 cm world's robot
  // pose (-21.67, 47.12, 28.2 deg) turned back by -90 deg.
  StageWorldOptions o;
  o.rule = PixelRule::map_server(0.196, false);
  const World w = load_stage_world((kPlans / "ros_navigation_tutorials/worlds/willow-pr2.world").string(), o);
  EXPECT_EQ(w.width(), 526);
  EXPECT_EQ(w.height(), 584);
  EXPECT_NEAR(w.origin().x(), -52.6, 1e-9);
  EXPECT_NEAR(w.origin().y(), 0.0, 1e-9);
  // hospital_section: 1086 x 443 px stretched to 40 x 18 m, resampled at the finer 0.0368 m.
  const World h = load_stage_world((kPlans / "stage/worlds/everything.world").string());
  EXPECT_NEAR(h.resolution(), 40.0 / 1086, 1e-12);
  EXPECT_NEAR(h.origin().x(), -20.0, 0.02);
  EXPECT_NEAR(h.origin().y(), -9.0, 0.02);
}

// kth/SOURCES.md tables: "| name | ... | free area (m^2) | ..." (P2) and valid space (MapEx).
std::map<std::string, double> sources_table(int name_col, int value_col) {
  std::ifstream in(kPlans / "kth" / "SOURCES.md");
  std::map<std::string, double> out;
  std::string line;
  const std::regex row(R"(^\| (0510|5001|5002|5003|5004|5005)[^|]*\|.*)");
  while (std::getline(in, line)) {
    if (!std::regex_match(line, row)) continue;
    std::vector<std::string> cells;
    std::stringstream ss(line.substr(1));
    for (std::string c; std::getline(ss, c, '|');) cells.push_back(c);
    std::string name = cells.at(static_cast<std::size_t>(name_col));
    name.erase(0, name.find_first_not_of(' '));
    name.erase(name.find_last_not_of(' ') + 1);
    try {
      out[name] = std::stod(cells.at(static_cast<std::size_t>(value_col)));
    } catch (const std::exception&) {
    }
  }
  return out;
}

TEST(WorldLoader, LoadsEveryKthPlanWithItsDocumentedArea) {
  const auto p2_free = sources_table(0, 4);      // P2 rows: free area column
  const auto mapex_valid = sources_table(0, 4);  // MapEx rows: valid space column
  int p2 = 0;
  for (const auto& row : read_csv(kPlans / "kth" / "kth_index.csv")) {
    const std::string file = row.at("file");
    if (file.rfind("p2explore/", 0) != 0 || fs::path(file).extension() != ".png") continue;
    SCOPED_TRACE(file);
    const World w = load_image_world((kPlans / "kth" / file).string(), {0.2, {0, 0}, PixelRule::only_white()});
    ++p2;
    const std::string name = fs::path(file).filename().string();
    if (file.find("/floor_plans/") != std::string::npos && p2_free.count(name)) {
      EXPECT_NEAR(w.free_area_m2(), p2_free.at(name), 1.0);  // table rounds to 1 m^2
    }
    EXPECT_GT(w.free_area_m2(), 40.0);
  }
  EXPECT_EQ(p2, 82);  // 40 plain + 40 cluttered + 2 test copies
  int mapex = 0;
  for (const auto& dir : fs::directory_iterator(kPlans / "kth" / "mapex_kth_test_maps")) {
    if (!dir.is_directory()) continue;
    SCOPED_TRACE(dir.path().string());
    const World occ = load_image_world((dir.path() / "occ_map.png").string(), {0.05, {0, 0}, {}});
    // valid_space: 0 = not room space, k >= 1 = room id.
    const World valid =
        load_image_world((dir.path() / "valid_space.png").string(), {0.05, {0, 0}, {0.0, false, PixelChannel::kMean}});
    EXPECT_EQ(occ.width(), valid.width());
    EXPECT_NEAR(valid.free_area_m2(), mapex_valid.at(dir.path().filename().string()), 1.0);
    EXPECT_GT(occ.width_m(), 39.0);
    EXPECT_LT(occ.width_m(), 136.0);
    ++mapex;
  }
  EXPECT_EQ(mapex, 14);
}

}  // namespace
}  // namespace lookahead::exploration
