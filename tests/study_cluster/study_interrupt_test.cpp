// SPDX-License-Identifier: MIT
// A local study stopped by SIGTERM writes results.csv, summary.md and missing.txt for the
// missions that finished, leaves nothing half-written that looks finished, and resumes.
#include <signal.h>

#include "cluster_test_support.hpp"

namespace lookahead::test {
namespace {

const std::string kBin = LOOKAHEAD_BINARY;

std::size_t data_rows(const fs::path& csv) {
  std::ifstream in(csv);
  std::size_t rows = 0;
  for (std::string line; std::getline(in, line);) rows += line.empty() ? 0 : 1;
  return rows == 0 ? 0 : rows - 1;
}

TEST(StudyInterrupt, WritesTheResultsOfTheFinishedMissions) {
  const TempDir tmp("lookahead-study-interrupt");
  std::ofstream(tmp.path / "s.yaml") << tiny_study("s", tmp.path / "out", 3, 40);
  const Shell started = shell(kBin + " study " + (tmp.path / "s.yaml").string() + " --jobs 1 > " +
                              (tmp.path / "log.txt").string() + " 2>&1 & echo $!");
  const pid_t pid = static_cast<pid_t>(std::stol(started.output));
  const fs::path out = tmp.path / "out";
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (finished_runs(out).size() < 2 && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  ASSERT_EQ(::kill(pid, SIGTERM), 0);
  for (int i = 0; i < 200 && ::kill(pid, 0) == 0; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  ASSERT_NE(::kill(pid, 0), 0) << "still running";
  const std::string log = read_file(tmp.path / "log.txt");
  EXPECT_NE(log.find("writing the results of the finished runs"), std::string::npos) << log;

  const std::size_t finished = finished_runs(out).size();
  ASSERT_LT(finished, 12u) << "the study ended before the signal";
  EXPECT_EQ(data_rows(out / "results.csv"), finished);
  std::size_t missing = 0;
  for (const char c : read_file(out / "missing.txt")) missing += c == '\n' ? 1 : 0;
  EXPECT_EQ(missing, 12 - finished);
  EXPECT_NE(
      read_file(out / "summary.md").find(std::to_string(12 - finished) + " of 12 planned missions are not finished"),
      std::string::npos);

  const Shell again = shell(kBin + " study " + (tmp.path / "s.yaml").string() + " --jobs 2");
  ASSERT_EQ(again.code, 0) << again.output;
  EXPECT_NE(again.output.find(std::to_string(12 - finished) + " run(s) executed"), std::string::npos) << again.output;
  EXPECT_EQ(data_rows(out / "results.csv"), 12u);
  // The staging folder of the mission the signal abandoned is gone.
  EXPECT_EQ(std::distance(fs::directory_iterator(out / "runs"), fs::directory_iterator()), 12);
}

}  // namespace
}  // namespace lookahead::test
