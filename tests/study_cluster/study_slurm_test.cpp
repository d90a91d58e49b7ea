// SPDX-License-Identifier: MIT
// A study as a real Slurm job array on a one-node cluster (scripts/slurm_local.sh): the
// merged results equal the local run's, and an array cancelled part-way and resubmitted
// runs only what is missing, losing and duplicating nothing.
#include <regex>

#include "cluster_test_support.hpp"

namespace lookahead::test {
namespace {

const std::string kBin = LOOKAHEAD_BINARY;

// "array job 12, merge job 13" from `lookahead study slurm --submit`.
std::pair<std::string, std::string> job_ids(const std::string& output) {
  std::smatch m;
  if (!std::regex_search(output, m, std::regex("array job ([0-9]+), merge job ([0-9]+)"))) return {};
  return {m[1], m[2]};
}

using StudyArray = SlurmCluster;

TEST_F(StudyArray, MergedArrayEqualsTheLocalStudy) {
  const TempDir tmp("lookahead-study-array");
  std::ofstream(tmp.path / "local.yaml") << tiny_study("tiny", tmp.path / "local", 3, 8);
  std::ofstream(tmp.path / "array.yaml") << tiny_study("tiny", tmp.path / "array", 3, 8);
  Shell r = shell(kBin + " study " + (tmp.path / "local.yaml").string() + " --jobs 2");
  ASSERT_EQ(r.code, 0) << r.output;

  r = shell("cd " + tmp.path.string() + " && " + kBin + " study slurm array.yaml --shards 4 --submit");
  ASSERT_EQ(r.code, 0) << r.output;
  const auto [array, merge] = job_ids(r.output);
  ASSERT_FALSE(merge.empty()) << r.output;
  ASSERT_TRUE(wait_for_job(merge, 240)) << job_state(array) << job_state(merge);
  EXPECT_NE(job_state(merge).find("COMPLETED"), std::string::npos) << job_state(merge);
  EXPECT_EQ(job_state(array), "JobState=COMPLETED\n");

  const auto local = results_without_timing(tmp.path / "local/results.csv");
  const auto merged = results_without_timing(tmp.path / "array/results.csv");
  EXPECT_EQ(local.size(), 13u);  // header + 12 missions
  EXPECT_EQ(merged, local);
  EXPECT_EQ(read_file(tmp.path / "array/plan.csv"), read_file(tmp.path / "local/plan.csv"));
  EXPECT_EQ(read_file(tmp.path / "array/overall.csv"), read_file(tmp.path / "local/overall.csv"));
  for (int task = 0; task < 4; ++task) {
    const fs::path log = tmp.path / ("array/slurm/logs/array_" + array + "_" + std::to_string(task) + ".log");
    EXPECT_TRUE(fs::exists(log)) << log;
    EXPECT_TRUE(fs::exists(tmp.path / ("array/logs/progress_" + std::to_string(task) + "_of_4.log")));
  }
  EXPECT_TRUE(fs::exists(tmp.path / "array/report.html"));
  EXPECT_EQ(read_file(tmp.path / "array/missing.txt"), "");
}

TEST_F(StudyArray, CancelledArrayResubmittedRunsOnlyWhatIsMissing) {
  const TempDir tmp("lookahead-study-cancel");
  std::ofstream(tmp.path / "study.yaml") << tiny_study("cancel", tmp.path / "out", 3, 40);
  const std::string submit = "cd " + tmp.path.string() + " && " + kBin + " study slurm study.yaml --shards 3 --submit";
  Shell r = shell(submit);
  ASSERT_EQ(r.code, 0) << r.output;
  const auto [array, merge] = job_ids(r.output);
  ASSERT_FALSE(merge.empty()) << r.output;

  // Cancel once a few missions are done and the rest are not.
  const fs::path out = tmp.path / "out";
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(180);
  while (finished_runs(out).size() < 3 && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  ASSERT_EQ(shell("scancel " + array + " " + merge).code, 0);
  ASSERT_TRUE(wait_for_job(array, 60));
  ASSERT_TRUE(wait_for_job(merge, 60));
  const std::set<std::string> before = finished_runs(out);
  ASSERT_GE(before.size(), 3u);
  ASSERT_LT(before.size(), 12u) << "the array finished before it was cancelled";
  std::map<std::string, fs::file_time_type> stamps;
  for (const std::string& run : before) stamps[run] = fs::last_write_time(out / "runs" / run / "run.json");

  r = shell(submit);
  ASSERT_EQ(r.code, 0) << r.output;
  const auto [array2, merge2] = job_ids(r.output);
  ASSERT_TRUE(wait_for_job(merge2, 240)) << job_state(array2);
  EXPECT_EQ(job_state(array2), "JobState=COMPLETED\n");

  const std::set<std::string> after = finished_runs(out);
  EXPECT_EQ(after.size(), 12u);
  // Nothing else: the merge job removed the staging folders of the killed missions.
  EXPECT_EQ(std::distance(fs::directory_iterator(out / "runs"), fs::directory_iterator()), 12);
  for (const auto& [run, stamp] : stamps)  // finished before: not run again
    EXPECT_EQ(fs::last_write_time(out / "runs" / run / "run.json"), stamp) << run;
  std::size_t executed = 0;  // the resubmitted tasks say how many they ran
  for (int task = 0; task < 3; ++task) {
    const std::string log = read_file(out / ("slurm/logs/array_" + array2 + "_" + std::to_string(task) + ".log"));
    std::smatch m;
    ASSERT_TRUE(std::regex_search(log, m, std::regex("([0-9]+) run\\(s\\) executed"))) << log;
    executed += std::stoul(m[1]);
  }
  EXPECT_EQ(executed, 12 - before.size());
  const auto rows = results_without_timing(out / "results.csv");
  EXPECT_EQ(rows.size(), 13u);
  EXPECT_EQ(std::set<std::string>(rows.begin(), rows.end()).size(), rows.size());  // no duplicate
  EXPECT_EQ(read_file(out / "missing.txt"), "");
}

}  // namespace
}  // namespace lookahead::test
