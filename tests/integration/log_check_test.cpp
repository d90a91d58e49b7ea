// SPDX-License-Identifier: MIT
// `lookahead check` on every log in shared/data: the known quirks of each are reported
// (SOURCES.md): CSAIL's scans written three times and its 81.91 m no-returns, fr101's
// corrected log ending before the raw one, the gaps of the corrected Intel and flirtlib logs.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

namespace lookahead::slam {
namespace {

namespace fs = std::filesystem;
const std::string kData = std::string(LOOKAHEAD_SHARED_DIR) + "/data/";

struct Check {
  int code = -1;
  nlohmann::json report;
  bool has(const std::string& finding, const std::string& severity) const {
    for (const auto& f : report["findings"]) {
      if (f["code"] == finding && f["severity"] == severity) return true;
    }
    return false;
  }
};

Check check(const std::string& args) {
  const fs::path out = fs::temp_directory_path() / ("lookahead-check-" + std::to_string(::getpid()) + ".json");
  const int status =
      std::system((std::string(LOOKAHEAD_BINARY) + " check --json " + args + " > " + out.string()).c_str());
  std::stringstream text;
  text << std::ifstream(out).rdbuf();
  fs::remove(out);
  return {WEXITSTATUS(status), nlohmann::json::parse(text.str())};
}

#define REQUIRE_DATA(file) \
  if (!fs::exists(kData + (file))) GTEST_SKIP() << "no shared data: " << kData + (file)

TEST(LogCheck, CsailOldCarmenHasEveryScanThreeTimesAnd8191NoReturns) {
  REQUIRE_DATA("mit-csail/csail-oldcarmen.log");
  const Check c = check(kData + "mit-csail/csail-oldcarmen.log");
  EXPECT_EQ(c.report["scans"], 1988);
  EXPECT_EQ(c.report["scan_source"], "FLASER");
  // ROBOTLASER1 and RAWLASER1 copies of the 1,988 FLASER scans (one copy differs in a reading).
  EXPECT_GE(c.report["duplicate_scans"].get<int>(), 2 * 1988 - 5);
  EXPECT_TRUE(c.has("duplicate_scans", "note"));
  EXPECT_NEAR(c.report["no_return_value_m"].get<double>(), 81.91, 1e-4);
  EXPECT_LE(c.code, 1);
}

TEST(LogCheck, CsailNewCarmenCarriesEachRobotlaserAgainAsRawlaser) {
  REQUIRE_DATA("mit-csail/csail-newcarmen.log");
  const Check c = check(kData + "mit-csail/csail-newcarmen.log");
  EXPECT_EQ(c.report["scan_source"], "ROBOTLASER1");
  EXPECT_GE(c.report["duplicate_scans"].get<int>(), 1988 - 5);
  EXPECT_NEAR(c.report["no_return_value_m"].get<double>(), 81.91, 1e-4);
}

TEST(LogCheck, Fr101ReferenceEndsBeforeTheLog) {
  REQUIRE_DATA("fr101/fr101.carmen.log");
  const Check c = check(kData + "fr101/fr101.carmen.log --reference " + kData + "fr101/fr101.carmen.gfs.log");
  EXPECT_EQ(c.report["scans"], 4758);
  EXPECT_TRUE(c.has("reference_ends_early", "warning")) << c.report.dump(2);
  EXPECT_EQ(c.code, 1);
  const Check alone = check(kData + "fr101/fr101.carmen.log");
  EXPECT_FALSE(alone.has("reference_ends_early", "warning"));
}

TEST(LogCheck, CorrectedIntelLogHasGaps) {
  REQUIRE_DATA("intel/intel.gfs.log");
  const Check c = check(kData + "intel/intel.gfs.log");
  EXPECT_EQ(c.report["scans"], 910);
  EXPECT_TRUE(c.has("gaps", "warning")) << c.report.dump(2);
  EXPECT_GT(c.report["largest_gaps"][0]["seconds"].get<double>(), 13.0);  // 13.9 s before t = 954.4 s
  EXPECT_TRUE(c.has("time_backwards", "warning"));
  EXPECT_EQ(c.code, 1);
}

TEST(LogCheck, FlirtlibLogsAreReadAndCanBeMapped) {
  for (const char* name :
       {"derived-flirtlib/intel-lab.log", "derived-flirtlib/fr079.log", "derived-flirtlib/mit-cscail.log"}) {
    REQUIRE_DATA(name);
    const Check c = check(kData + name);
    EXPECT_GT(c.report["scans"].get<int>(), 100) << name;
    EXPECT_LE(c.code, 1) << name;
  }
}

TEST(LogCheck, MrptRawlogCanBeMapped) {
  const std::string rawlog = "/usr/share/mrpt/datasets/2006-01ENE-21-SENA_Telecom Faculty_one_loop_only.rawlog";
  if (!fs::exists(rawlog)) GTEST_SKIP() << "mrpt-common not installed";
  const Check c = check("'" + rawlog + "'");
  EXPECT_EQ(c.report["scans"], 225);
  EXPECT_TRUE(c.report["odometry_moves"].get<bool>());
  EXPECT_LE(c.code, 1);
}

TEST(LogCheck, UnreadableInputExitsTwoWithTheReason) {
  const Check c = check("/nonexistent/run.bag");
  EXPECT_EQ(c.code, 2);
  EXPECT_TRUE(c.has("unreadable", "error"));
}

}  // namespace
}  // namespace lookahead::slam
