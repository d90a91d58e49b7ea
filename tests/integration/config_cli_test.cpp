// SPDX-License-Identifier: MIT
// `lookahead config`, the front door to every configuration section: the shipped defaults and
// docs/config.md are what the code prints, every shipped file loads, bad files are refused.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace {

namespace fs = std::filesystem;

struct Result {
  int code;
  std::string output;
};

Result run(const std::string& args) {
  const std::string cmd = std::string(LOOKAHEAD_BINARY) + " " + args + " 2>&1";
  FILE* pipe = popen(cmd.c_str(), "r");
  std::string out;
  char buf[4096];
  for (std::size_t n; (n = fread(buf, 1, sizeof buf, pipe)) > 0;) out.append(buf, n);
  const int status = pclose(pipe);
  return {WEXITSTATUS(status), out};
}

std::string read(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

const fs::path kSource = LOOKAHEAD_SOURCE_DIR;

TEST(ConfigCli, EveryShippedDefaultFileIsTheDump) {
  for (const char* section : {"slam", "segslam", "segslam3d", "hybrid", "slam3d", "mission"}) {
    const Result r = run(std::string("config dump ") + section);
    ASSERT_EQ(r.code, 0) << r.output;
    EXPECT_EQ(r.output, read(kSource / "config" / section / "default.yaml"))
        << "regenerate with: lookahead config dump " << section << " > config/" << section << "/default.yaml";
  }
}

TEST(ConfigCli, ReferencePageIsCurrent) {
  const Result r = run("config reference");
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_EQ(r.output, read(kSource / "docs" / "config.md"))
      << "regenerate with: lookahead config reference > docs/config.md";
  for (const char* key : {"weight_exponent", "coverage_goal", "max_motion_error", "pixel_rule"}) {
    EXPECT_NE(r.output.find(key), std::string::npos) << key;
  }
}

TEST(ConfigCli, EveryShippedFileChecksOk) {
  int checked = 0;
  for (const auto& e : fs::recursive_directory_iterator(kSource / "config")) {
    if (e.path().extension() != ".yaml") continue;
    const Result r = run("config check " + e.path().string());
    EXPECT_EQ(r.code, 0) << e.path() << ": " << r.output;
    ++checked;
  }
  EXPECT_GE(checked, 8);
}

TEST(ConfigCli, TheStudyTemplateIsALoadableStudy) {
  const fs::path dir = fs::temp_directory_path() / "lookahead-config-cli";
  fs::create_directories(dir / "study");
  std::ofstream(dir / "study" / "template.yaml") << run("config dump study").output;
  const Result r = run("config check " + (dir / "study" / "template.yaml").string());
  EXPECT_EQ(r.code, 0) << r.output;
  fs::remove_all(dir);
}

TEST(ConfigCli, BadFilesNameFileLineKeyAndValue) {
  const fs::path dir = fs::temp_directory_path() / "lookahead-config-cli-bad";
  fs::create_directories(dir / "mission");
  const fs::path bad = dir / "mission" / "bad.yaml";
  std::ofstream(bad) << "mission:\n  coverage_goal: 0.9\n  stuck_tme: 30\n";
  Result r = run("config check " + bad.string());
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find("bad.yaml:3"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("stuck_tme"), std::string::npos) << r.output;
  std::ofstream(bad) << "filter:\n  particles: many\n";
  r = run("config check " + bad.string() + " --section slam");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find("bad.yaml:2"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("many"), std::string::npos) << r.output;
  r = run("config check " + (dir / "elsewhere.yaml").string());
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.output.find("--section"), std::string::npos) << r.output;
  r = run("config dump nonsense");
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.output.find("slam | segslam"), std::string::npos) << r.output;
  fs::remove_all(dir);
}

// A map_server world in config/worlds/ is checked by the world loader: its size is reported,
// and a bad value is named with file, line and key.
TEST(ConfigCli, WorldFilesLoadThroughTheWorldLoader) {
  Result r = run("config check " + (kSource / "config" / "worlds" / "intel.yaml").string());
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("map_server world, 44.40 m x 42.40 m"), std::string::npos) << r.output;
  const fs::path dir = fs::temp_directory_path() / "lookahead-config-cli-world";
  fs::create_directories(dir / "worlds");
  const fs::path bad = dir / "worlds" / "bad.yaml";
  std::ofstream(bad) << "image: missing.pgm\nresolution: -0.05\norigin: [0, 0, 0]\n";
  r = run("config check " + bad.string());
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.output.find("bad.yaml:2"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("resolution"), std::string::npos) << r.output;
  fs::remove_all(dir);
}

}  // namespace
