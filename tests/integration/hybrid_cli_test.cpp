// SPDX-License-Identifier: MIT
// `lookahead slam --method hybrid` on the real fr101 log and `lookahead hybrid-sim` end to
// end: the outputs exist and say something plausible; bad input exits non-zero.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

namespace {

namespace fs = std::filesystem;

int run(const std::string& args, const fs::path& log) {
  const int status = std::system((std::string(LOOKAHEAD_BINARY) + " " + args + " > " + log.string() + " 2>&1").c_str());
  return WEXITSTATUS(status);
}

fs::path temp_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("lookahead-hybrid-" + name + "-" + std::to_string(::getpid()));
  fs::create_directories(d);
  return d;
}

TEST(HybridCli, MapsTheFirstScansOfFr101AndScoresThem) {
  const std::string log = std::string(LOOKAHEAD_SHARED_DIR) + "/data/fr101/fr101.carmen.log";
  if (!fs::exists(log)) GTEST_SKIP() << log << " not found";
  const fs::path out = temp_dir("fr101");
  ASSERT_EQ(
      run("slam " + log + " --method hybrid --max-scans 800 --particles 30 --out " + out.string(), out / "log.txt"), 0);
  EXPECT_TRUE(fs::exists(out / "map.png"));
  EXPECT_TRUE(fs::exists(out / "trajectory.txt"));
  EXPECT_TRUE(fs::exists(out / "landmarks.txt"));
  const nlohmann::json j = nlohmann::json::parse(std::ifstream(out / "run.json"));
  EXPECT_EQ(j["scans"], 800);
  EXPECT_GT(j["landmarks"].get<int>(), 10);
  EXPECT_GT(j["fusions"].get<int>(), 5);
  ASSERT_TRUE(j["error_vs_reference"].contains("trans_mean_m"));
  EXPECT_GT(j["error_vs_reference"]["relations_used"].get<int>(), 20);
  EXPECT_LT(j["error_vs_reference"]["trans_mean_m"].get<double>(), 0.3);
  fs::remove_all(out);
}

// CSAIL's reference is a Radish corrected log without usable stamps: its scans are paired
// with the raw log's by their ranges; csail.yaml's extractor settings reach the run.
TEST(HybridCli, ScoresCsailAgainstItsCorrectedLogWithTheCsailConfig) {
  const std::string log = std::string(LOOKAHEAD_SHARED_DIR) + "/data/mit-csail/csail-oldcarmen.log";
  if (!fs::exists(log)) GTEST_SKIP() << log << " not found";
  const fs::path out = temp_dir("csail");
  const std::string config = std::string(LOOKAHEAD_SOURCE_DIR) + "/config/hybrid/csail.yaml";
  ASSERT_EQ(run("slam " + log + " --method hybrid --max-scans 400 --particles 30 --config " + config + " --out " +
                    out.string(),
                out / "log.txt"),
            0);
  const nlohmann::json j = nlohmann::json::parse(std::ifstream(out / "run.json"));
  const auto& e = j["error_vs_reference"];
  ASSERT_TRUE(e.contains("trans_mean_m")) << "no reference found or paired";
  EXPECT_NE(e["reference"].get<std::string>().find("csail.corrected.log"), std::string::npos);
  EXPECT_GT(e["relations_used"].get<int>(), 50);  // ~1 corrected scan per 5 raw ones
  EXPECT_LT(e["trans_mean_m"].get<double>(), 0.5);
  EXPECT_NE(j["configuration_yaml"].get<std::string>().find("split_tolerance: 0.12"), std::string::npos);
  EXPECT_GT(j["landmark_observations"].get<int>(), 4 * 400) << "csail.yaml should give several landmarks per scan";
  fs::remove_all(out);
}

TEST(HybridCli, SimulationFiguresAndABadConfig) {
  const fs::path out = temp_dir("sim");
  // The paper's feature density (35 in 120 m x 120 m): 6 features in 50 m x 50 m.
  std::ofstream(out / "small.yaml") << "simulation:\n  world_size: 50\n  features: 6\n  inset: 8\n"
                                       "  loop_overlap: 10\nfastslam:\n  particles: 30\n";
  ASSERT_EQ(run("hybrid-sim --no-study --config " + (out / "small.yaml").string() + " --out " + out.string(),
                out / "log.txt"),
            0);
  for (const char* f : {"fig3_trace_compass.png", "fig4_trace.png", "nees.png", "world.png", "run.json"}) {
    EXPECT_TRUE(fs::exists(out / f)) << f;
  }
  std::ofstream(out / "bad.yaml") << "fusion:\n  perod: 3\n";
  EXPECT_EQ(
      run("hybrid-sim --no-study --config " + (out / "bad.yaml").string() + " --out " + out.string(), out / "bad.txt"),
      2);
  std::ifstream in(out / "bad.txt");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("bad.yaml:2"), std::string::npos) << text;
  EXPECT_NE(text.find("fusion.perod"), std::string::npos) << text;
  fs::remove_all(out);
}

}  // namespace
