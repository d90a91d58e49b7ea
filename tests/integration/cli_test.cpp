// SPDX-License-Identifier: MIT
// The `lookahead` command end to end: outputs of a run, and bad input ending with a clear
// error and a non-zero exit.
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

Result shell(const std::string& cmd) {
  // pid + counter: ctest runs tests of this file in parallel processes, whose rand() agree.
  static int counter = 0;
  const fs::path out = fs::temp_directory_path() /
                       ("lookahead-cli-" + std::to_string(::getpid()) + "-" + std::to_string(counter++) + ".txt");
  const int status = std::system((cmd + " > " + out.string() + " 2>&1").c_str());
  std::ifstream in(out);
  std::stringstream text;
  text << in.rdbuf();
  fs::remove(out);
  return {WEXITSTATUS(status), text.str()};
}

class Cli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = fs::temp_directory_path() / ("lookahead-cli-test-" + std::to_string(::getpid()));
    fs::create_directories(dir);
  }
  void TearDown() override { fs::remove_all(dir); }
  fs::path dir;
  const std::string bin = LOOKAHEAD_BINARY;
};

TEST_F(Cli, SlamOnTheDefaultLogWritesEveryOutput) {
  const Result r = shell(bin + " slam --out " + dir.string() + " --particles 10");
  ASSERT_EQ(r.code, 0) << r.output;
  for (const char* f : {"map.pgm", "map.yaml", "map.png", "trajectory.txt", "run.json"}) {
    EXPECT_TRUE(fs::exists(dir / f)) << f;
  }
  nlohmann::json j;
  std::ifstream(dir / "run.json") >> j;
  EXPECT_EQ(j["scans"].get<int>(), 225);  // the MRPT one-loop rawlog
  EXPECT_GT(j["updates"].get<int>(), 50);
  EXPECT_GT(j["peak_memory_mb"].get<double>(), 1.0);
  EXPECT_EQ(j["neff_history"].size(), j["updates"].get<std::size_t>());
  const Result e = shell(bin + " eval --map " + (dir / "map.yaml").string());
  EXPECT_EQ(e.code, 0) << e.output;
  EXPECT_NE(e.output.find("map entropy"), std::string::npos);
}

TEST_F(Cli, MalformedLogStopsWithFileLineAndField) {
  const fs::path log = dir / "bad.log";
  std::ofstream(log) << "ODOM 0 0 0 0 0 0 1 h 1\nFLASER 3 1.0 2.0 x 0 0 0 0 0 0 2 h 2\n";
  const Result r = shell(bin + " slam " + log.string() + " --out " + (dir / "o").string());
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find("bad.log:2"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("'x'"), std::string::npos) << r.output;
  // With a readable scan beside the bad line, --skip-bad-lines maps it and names what it skipped.
  std::ofstream(log) << "ODOM 0 0 0 0 0 0 1 h 1\nFLASER 3 1.0 2.0 3.0 0 0 0 0 0 0 1.5 h 1.5\n"
                        "FLASER 3 1.0 2.0 x 0 0 0 0 0 0 2 h 2\n";
  const Result skip = shell(bin + " slam " + log.string() + " --skip-bad-lines --out " + (dir / "o").string());
  EXPECT_EQ(skip.code, 0) << skip.output;
  EXPECT_NE(skip.output.find("1 malformed lines skipped"), std::string::npos) << skip.output;
  EXPECT_NE(skip.output.find("bad.log:3"), std::string::npos) << skip.output;
}

TEST_F(Cli, MissingFilesAndBadConfigsAreErrorsNotCrashes) {
  EXPECT_EQ(shell(bin + " slam /no/such/log.clf").code, 2);
  const fs::path cfg = dir / "bad.yaml";
  std::ofstream(cfg) << "filter:\n  particles: many\n";
  const Result r = shell(bin + " slam --config " + cfg.string());
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find("bad.yaml:2"), std::string::npos) << r.output;
}

}  // namespace

namespace {

TEST_F(Cli, ExploreWritesMapPicturesAnimationAndRunJson) {
  const Result r = shell(bin + " explore --time-limit 40 --particles 5 --log --out " + dir.string());
  ASSERT_EQ(r.code, 0) << r.output;
  for (const char* f :
       {"map.pgm", "map.yaml", "map.png", "coverage.png", "animation.mp4", "trajectory.txt", "run.json", "run.log"}) {
    EXPECT_TRUE(fs::exists(dir / f)) << f;
  }
  nlohmann::json j;
  std::ifstream(dir / "run.json") >> j;
  EXPECT_EQ(j["status"], "time_limit");
  EXPECT_EQ(j["collisions"].get<int>(), 0);
  EXPECT_GT(j["coverage"].get<double>(), 0.02);
  // The simulated run replays through `lookahead slam`.
  const Result replay =
      shell(bin + " slam " + (dir / "run.log").string() + " --particles 5 --out " + (dir / "replay").string());
  EXPECT_EQ(replay.code, 0) << replay.output;
}

TEST_F(Cli, ExploreRejectsBadWorldsAndStrategies) {
  EXPECT_NE(shell(bin + " explore --world /no/such.yaml --out " + dir.string()).code, 0);
  const Result r = shell(bin + " explore --strategy random --out " + dir.string());
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.output.find("random"), std::string::npos) << r.output;
}

}  // namespace

namespace {

TEST_F(Cli, PredictOnASavedMapWritesItsPictureAndFigures) {
  const fs::path run = dir / "maze";
  Result r = shell(bin + " explore --world maze --pose truth --time-limit 60 --no-animation --out " + run.string());
  ASSERT_EQ(r.code, 0) << r.output;
  r = shell(bin + " predict " + (run / "map.yaml").string() + " --target 2.5,5.0 --out " + dir.string());
  ASSERT_TRUE(r.code == 0 || r.code == 3) << r.output;  // 3: no hypothesis cleared the threshold
  EXPECT_TRUE(fs::exists(dir / "prediction.png"));
  std::ifstream in(dir / "prediction.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_TRUE(j.contains("status"));
  EXPECT_EQ(fs::exists(dir / "hypothesis.pgm"), r.code == 0);
  r = shell(bin + " predict " + (run / "map.pgm").string() + " --target 2.5,5.0 --out " + dir.string());
  EXPECT_TRUE(r.code == 0 || r.code == 3) << r.output;  // the PGM finds its YAML beside it
  // The predictor section of a config file; a misspelt key is refused with file and line.
  const fs::path config = dir / "predictor.yaml";
  std::ofstream(config) << "predictor:\n  similarity_threshold: 0.4\n";
  r = shell(bin + " predict " + (run / "map.yaml").string() + " --target 2.5,5.0 --config " + config.string() +
            " --out " + dir.string());
  EXPECT_TRUE(r.code == 0 || r.code == 3) << r.output;
  std::ofstream(config) << "predictor:\n  similarity_treshold: 0.4\n";
  r = shell(bin + " predict " + (run / "map.yaml").string() + " --target 2.5,5.0 --config " + config.string());
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("predictor.yaml:2"), std::string::npos) << r.output;
}

TEST_F(Cli, ExploreKeepsTheConfigsSeedUnlessSeedIsGiven) {
  // A study's run_config.yaml replays its run: its mission.seed must not be reset to 1.
  const fs::path config = dir / "seed3.yaml";
  std::ofstream(config) << "mission:\n  seed: 3\n";
  const auto seed_of = [&](const std::string& extra) {
    const fs::path out = dir / ("seed" + std::to_string(extra.size()));
    const Result r = shell(bin + " explore --world maze --pose truth --time-limit 3 --no-animation --config " +
                           config.string() + extra + " --out " + out.string());
    EXPECT_EQ(r.code, 0) << r.output;
    nlohmann::json j;
    std::ifstream(out / "run.json") >> j;
    return j["seed"].get<int>();
  };
  EXPECT_EQ(seed_of(""), 3);
  EXPECT_EQ(seed_of(" --seed 2"), 2);
}

TEST_F(Cli, PredictRejectsMissingMapsAndBadTargets) {
  Result r = shell(bin + " predict " + (dir / "none.pgm").string() + " --target 1,2");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("none"), std::string::npos) << r.output;
  r = shell(bin + " predict " + (dir / "none.yaml").string() + " --target 1");
  EXPECT_NE(r.code, 0);
}

TEST_F(Cli, SlamWithPredictReportsItsPredictions) {
  const Result r = shell(bin + " slam --predict --particles 5 --max-scans 400 --out " + dir.string());
  ASSERT_EQ(r.code, 0) << r.output;
  std::ifstream in(dir / "run.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  ASSERT_TRUE(j.contains("prediction"));
  const auto& p = j["prediction"];
  EXPECT_GT(p["requests"].get<int>(), 0);
  // A replay waits for its predictions by default: every request but the last one in
  // flight reaches the filter, each with its best Psi recorded.
  EXPECT_GE(p["records"].size() + 1, p["requests"].get<std::size_t>());
  EXPECT_EQ(p["records"].size(), static_cast<std::size_t>(p["hypotheses"].get<int>() + p["no_match"].get<int>() +
                                                          p["no_control_point"].get<int>()));
  EXPECT_NE(p["options_yaml"].get<std::string>().find("wait_for_predictions: true"), std::string::npos);
}

}  // namespace
