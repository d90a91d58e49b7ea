// SPDX-License-Identifier: MIT
// Bad input to `lookahead study plan|run|merge|slurm` ends with an error that names the
// problem and a non-zero exit, and runs nothing.
#include "cluster_test_support.hpp"

namespace lookahead::test {
namespace {

const std::string kBin = LOOKAHEAD_BINARY;

class StudyCli : public ::testing::Test {
 protected:
  TempDir tmp{"lookahead-study-cli"};
  fs::path study() const { return tmp.path / "s.yaml"; }
  void write_study(double time_limit) const {
    std::ofstream(study()) << tiny_study("s", tmp.path / "out", 1, time_limit);
  }
  Shell study_cmd(const std::string& args) const { return shell(kBin + " study " + args); }
};

TEST_F(StudyCli, ShardSpecsMustBeIOfN) {
  write_study(3);
  for (const char* bad : {"2of4", "1/", "/4", "1/0", "a/b", "1/4x", "+1/4"}) {
    const Shell r = study_cmd("run " + study().string() + " --shard " + bad);
    EXPECT_EQ(r.code, 2) << bad << r.output;
    EXPECT_NE(r.output.find(std::string("shard \"") + bad + "\""), std::string::npos) << r.output;
  }
  const Shell r = study_cmd("run " + study().string() + " --shard 4/4");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find("I must be < N"), std::string::npos) << r.output;
  const Shell env = shell("SLURM_ARRAY_TASK_ID=5 SLURM_ARRAY_TASK_COUNT=5 " + kBin + " study run " + study().string());
  EXPECT_EQ(env.code, 2);
  EXPECT_NE(env.output.find("SLURM_ARRAY_TASK_ID"), std::string::npos) << env.output;
  EXPECT_FALSE(fs::exists(tmp.path / "out/runs"));
  EXPECT_NE(study_cmd("dance " + study().string()).output.find("unknown verb"), std::string::npos);
}

TEST_F(StudyCli, AStudyChangedAfterPlanningRunsNothing) {
  write_study(3);
  Shell r = study_cmd("plan " + study().string());
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("4 mission(s)"), std::string::npos) << r.output;
  write_study(4);  // a longer time limit: every mission id changes
  r = study_cmd("run " + study().string() + " --shard 0/2");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("plan.csv:2"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("changed since `lookahead study plan`"), std::string::npos) << r.output;
  EXPECT_TRUE(finished_runs(tmp.path / "out").empty());
  ASSERT_EQ(study_cmd("plan " + study().string()).code, 0);
  r = study_cmd("run " + study().string() + " --shard 1/2 --jobs 1");
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_EQ(finished_runs(tmp.path / "out").size(), 2u);  // missions 1 and 3 of 0..3
  r = study_cmd("merge " + study().string());
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("2 of 4 planned missions are not finished"), std::string::npos) << r.output;
  EXPECT_EQ(read_file(tmp.path / "out/missing.txt"), "maze__nearest__1\ncorridor__nearest__1\n");
}

TEST_F(StudyCli, AMissingWorldIsNamed) {
  std::ofstream(study()) << "name: s\nout: " << (tmp.path / "out").string()
                         << "\nworlds:\n  - {name: maze}\n  - {name: plans/gone.png, resolution: 0.1}\n"
                         << "strategies: [nearest]\nseeds: [1]\n";
  for (const char* verb : {"plan", "run", "slurm"}) {
    const Shell r = study_cmd(std::string(verb) + " " + study().string());
    EXPECT_EQ(r.code, 2) << verb << r.output;
    EXPECT_NE(r.output.find("s.yaml:5"), std::string::npos) << verb << r.output;
    EXPECT_NE(r.output.find("plans/gone.png"), std::string::npos) << verb << r.output;
  }
}

TEST_F(StudyCli, SubmittingWithoutSbatchSaysSo) {
  write_study(3);
  const Shell r = shell("cd " + tmp.path.string() + " && PATH=/nonexistent " + kBin + " study slurm s.yaml --submit");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("sbatch is not on PATH"), std::string::npos) << r.output;
  // The scripts are written all the same, with the shard count and the throttle.
  const std::string array = read_file(tmp.path / "out/slurm/array.sbatch");
  EXPECT_NE(array.find("#SBATCH --array=0-3\n"), std::string::npos) << array;
  EXPECT_NE(array.find("--shard \"${SLURM_ARRAY_TASK_ID}/4\""), std::string::npos) << array;
  EXPECT_TRUE(fs::exists(tmp.path / "out/slurm/merge.sbatch"));
  EXPECT_EQ(shell("cd " + tmp.path.string() + " && " + kBin + " study slurm s.yaml --shards 5").code, 2);
}

}  // namespace
}  // namespace lookahead::test
