// SPDX-License-Identifier: MIT
// `lookahead slam3d` end to end: the outputs of a short run on each input kind, and the
// clear error for the method that is not on this branch yet.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

namespace {

namespace fs = std::filesystem;

struct Result {
  int code;
  std::string output;
};

Result run(const std::string& args, const fs::path& log) {
  const int status =
      std::system((std::string(LOOKAHEAD_BINARY) + " slam3d " + args + " > " + log.string() + " 2>&1").c_str());
  std::ifstream in(log);
  std::stringstream text;
  text << in.rdbuf();
  return {WEXITSTATUS(status), text.str()};
}

class Slam3dCli : public ::testing::Test {
 protected:
  void SetUp() override {
    static int counter = 0;
    dir = fs::temp_directory_path() /
          ("lookahead-slam3d-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    fs::create_directories(dir);
  }
  void TearDown() override { fs::remove_all(dir); }
  /// A SegSLAM run with `flag value` fails, names the flag and the value, and writes no run.json.
  void expect_segslam_rejects(const std::string& flag, const std::string& value) {
    const Result r =
        run("garage --method segslam --max-sweeps 3 " + flag + " " + value + " --out " + dir.string(), dir / "log.txt");
    EXPECT_NE(r.code, 0);
    EXPECT_NE(r.output.find(flag), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(value), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(dir / "run.json"));
  }
  fs::path dir;
};

TEST_F(Slam3dCli, GarageWritesMapPictureAndRunJson) {
  const Result r = run("garage --particles 2 --max-sweeps 6 --out " + dir.string(), dir / "log.txt");
  ASSERT_EQ(r.code, 0) << r.output;
  for (const char* f : {"map.bt", "world.bt", "trajectory.png", "trajectory.txt", "run.json"}) {
    EXPECT_TRUE(fs::exists(dir / f)) << f;
  }
  const nlohmann::json j = nlohmann::json::parse(std::ifstream(dir / "run.json"));
  EXPECT_EQ(j["sweeps"].get<int>(), 6);
  EXPECT_TRUE(j.contains("final_position_error_m"));
  EXPECT_GT(j["memory"]["mean_map_bytes"].get<double>(), 0.0);
}

TEST_F(Slam3dCli, ThreeDtkFolderIsAnInput) {
  const std::string dat = std::string(LOOKAHEAD_SHARED_DIR) + "/data/3d/3dtk_dat";
  const Result r = run("'" + dat + "' --particles 2 --out " + dir.string(), dir / "log.txt");
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_TRUE(fs::exists(dir / "map.bt"));
  EXPECT_TRUE(fs::exists(dir / "trajectory.png"));
}

// SegSLAM on a short garage drive with short segments: the outputs, and the segmentation in
// run.json.
TEST_F(Slam3dCli, SegslamWritesMapPictureAndRunJson) {
  const fs::path yaml = dir / "seg.yaml";
  std::ofstream(yaml) << "segmentation:\n  min_segment_updates: 3\n  max_motion_error: 0.1\n";
  const Result r = run("garage --method segslam --particles 2 --max-sweeps 12 --map-samples 2 --segslam-config '" +
                           yaml.string() + "' --out " + dir.string(),
                       dir / "log.txt");
  ASSERT_EQ(r.code, 0) << r.output;
  for (const char* f : {"map.bt", "world.bt", "trajectory.png", "trajectory.txt", "run.json"}) {
    EXPECT_TRUE(fs::exists(dir / f)) << f;
  }
  const nlohmann::json j = nlohmann::json::parse(std::ifstream(dir / "run.json"));
  EXPECT_EQ(j["method"], "segslam");
  EXPECT_EQ(j["sweeps"].get<int>(), 12);
  EXPECT_GE(j["segmentations"].get<int>(), 1);
  EXPECT_TRUE(j.contains("final_position_error_m"));
  EXPECT_EQ(j["sample_entropies"].size(), 2U);
  EXPECT_TRUE(j["share_by_segment"].get<bool>());  // the default
}

TEST_F(Slam3dCli, SearchPerParticleTurnsSegmentSharingOff) {
  const Result r =
      run("garage --method segslam --particles 2 --max-sweeps 4 --map-samples 1 --search-per-particle --out " +
              dir.string(),
          dir / "log.txt");
  ASSERT_EQ(r.code, 0) << r.output;
  const nlohmann::json j = nlohmann::json::parse(std::ifstream(dir / "run.json"));
  EXPECT_FALSE(j["share_by_segment"].get<bool>());
}

// The `locking:` keys of --segslam-config reach the 3D filter, and run.json counts what
// locking and merging did (a 12-sweep drive re-enters nothing: the counts are 0).
TEST_F(Slam3dCli, SegslamReadsTheLockingKeysAndCountsLockedAndMerged) {
  const fs::path yaml = dir / "lock.yaml";
  std::ofstream(yaml) << "locking:\n  lock: true\n  lock_max_error: 0.07\n  merge: true\n  merge_max_error: 0.09\n";
  const Result r = run("garage --method segslam --particles 2 --max-sweeps 12 --map-samples 1 --segslam-config '" +
                           yaml.string() + "' --out " + dir.string(),
                       dir / "log.txt");
  ASSERT_EQ(r.code, 0) << r.output;
  const nlohmann::json j = nlohmann::json::parse(std::ifstream(dir / "run.json"));
  const std::string params = j["configuration_yaml"].get<std::string>();
  for (const char* key : {"lock: true", "lock_max_error: 0.07", "merge: true", "merge_max_error: 0.09"}) {
    EXPECT_NE(params.find(key), std::string::npos) << key << " in\n" << params;
  }
  for (const char* key : {"locked_submaps", "locked_particle_updates", "merged_submaps", "submaps_with_maps"}) {
    ASSERT_TRUE(j.contains(key)) << key;
  }
  EXPECT_EQ(j["submaps_with_maps"].get<int>(), j["live_submaps"].get<int>() - j["merged_submaps"].get<int>());
}

TEST_F(Slam3dCli, SegslamConfigErrorsNameTheKey) {
  const fs::path yaml = dir / "bad.yaml";
  std::ofstream(yaml) << "matching:\n  icp_sigmaa: 1\n";
  const Result r =
      run("garage --method segslam --max-sweeps 3 --segslam-config '" + yaml.string() + "' --out " + dir.string(),
          dir / "log.txt");
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.output.find("icp_sigmaa"), std::string::npos) << r.output;
}

TEST_F(Slam3dCli, NegativeWideReentryRadiusIsRejectedWithItsValue) {
  expect_segslam_rejects("--wide-reentry-radius", "-3");
}

TEST_F(Slam3dCli, UnknownInputIsAnError) {
  const Result r = run("/nonexistent/place --out " + dir.string(), dir / "log.txt");
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.output.find("/nonexistent/place"), std::string::npos) << r.output;
}

}  // namespace
