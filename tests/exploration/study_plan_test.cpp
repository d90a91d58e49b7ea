// SPDX-License-Identifier: MIT
// A study's plan and shards: "I/N" parsing (with a property test over random text), the
// shards partitioning the plan, mission ids that depend on what determines a run and on
// nothing else, the plan check that refuses a changed study, the paired t-test and the
// Slurm scripts.
#include "lookahead/exploration/study_plan.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <regex>
#include <set>

#include "lookahead/exploration/study_shard.hpp"
#include "lookahead/exploration/study_slurm.hpp"
#include "lookahead/exploration/study_statistics.hpp"
#include "lookahead/slam/io/parse_error.hpp"
#include "temp_file.hpp"

namespace lookahead::exploration {
namespace {

TEST(Shard, ParsesIOfN) {
  const Shard s = parse_shard("3/8");
  EXPECT_EQ(s.index, 3u);
  EXPECT_EQ(s.count, 8u);
  EXPECT_EQ(parse_shard("0/1").count, 1u);
  for (const char* bad : {"", "3", "3/", "/8", "8/8", "9/8", "0/0", "-1/8", "1 /8", "1/8 ", "a/b", "1/8/2", "+1/8",
                          "1.0/8", "99999999999999999999/1"}) {
    EXPECT_THROW(parse_shard(bad), std::invalid_argument) << bad;
  }
  try {
    parse_shard("8/8");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("\"8/8\""), std::string::npos) << e.what();
  }
}

// Random text over the characters of a shard spec: either a valid shard that prints back
// as the same text, or std::invalid_argument; nothing else.
TEST(Shard, RandomTextParsesOrThrowsInvalidArgument) {
  std::mt19937 rng(7);
  const std::string alphabet = "0123456789/ -+x";
  for (int trial = 0; trial < 20000; ++trial) {
    std::string text;
    const int n = std::uniform_int_distribution<int>(0, 8)(rng);
    for (int i = 0; i < n; ++i)
      text += alphabet[std::uniform_int_distribution<std::size_t>(0, alphabet.size() - 1)(rng)];
    try {
      const Shard s = parse_shard(text);
      EXPECT_LT(s.index, s.count) << text;
      EXPECT_TRUE(std::regex_match(text, std::regex("[0-9]+/[0-9]+"))) << text;
      EXPECT_EQ(std::stoul(text.substr(0, text.find('/'))), s.index) << text;
      EXPECT_EQ(std::stoul(text.substr(text.find('/') + 1)), s.count) << text;
    } catch (const std::invalid_argument&) {
    }
  }
}

TEST(Shard, ShardsPartitionThePlan) {
  for (std::size_t missions : {0u, 1u, 7u, 12u, 1000u}) {
    for (std::size_t n : {1u, 3u, 4u, 13u}) {
      std::vector<int> seen(missions, 0);
      for (std::size_t i = 0; i < n; ++i) {
        for (const std::size_t m : shard_missions(missions, {i, n})) ++seen.at(m);
      }
      for (std::size_t m = 0; m < missions; ++m) EXPECT_EQ(seen[m], 1) << m << " of " << missions << " in " << n;
    }
  }
}

TEST(Shard, FromTheSlurmEnvironment) {
  ::unsetenv("SLURM_ARRAY_TASK_ID");
  ::unsetenv("SLURM_ARRAY_TASK_COUNT");
  EXPECT_FALSE(shard_from_slurm_environment());
  ::setenv("SLURM_ARRAY_TASK_ID", "2", 1);
  EXPECT_THROW(shard_from_slurm_environment(), std::invalid_argument);  // no count
  ::setenv("SLURM_ARRAY_TASK_COUNT", "5", 1);
  EXPECT_EQ(shard_from_slurm_environment()->index, 2u);
  ::setenv("SLURM_ARRAY_TASK_ID", "5", 1);
  EXPECT_THROW(shard_from_slurm_environment(), std::invalid_argument);
  ::unsetenv("SLURM_ARRAY_TASK_ID");
  ::unsetenv("SLURM_ARRAY_TASK_COUNT");
}

StudySpec spec_with(const std::string& dir, const std::string& extra) {
  return parse_study("name: p\nout: " + dir +
                         "/out\nworlds:\n  - {name: maze}\n  - {name: plan.pgm, "
                         "resolution: 0.1}\nstrategies: [nearest, utility]\nseeds: [1, 2, 3]\n" +
                         extra,
                     "p.yaml", dir);
}

TEST(StudyPlan, IdsDependOnWhatDeterminesTheRun) {
  const slam::test::TempPath dir;
  std::filesystem::create_directories(dir.str());
  std::ofstream(dir.str() + "/plan.pgm") << "P2\n2 1\n255\n255 0\n";
  const auto plan = plan_missions(spec_with(dir.str(), ""));
  ASSERT_EQ(plan.size(), 12u);
  std::set<std::string> ids;
  for (const PlannedMission& m : plan) {
    EXPECT_EQ(m.id.size(), 16u);
    ids.insert(m.id);
  }
  EXPECT_EQ(ids.size(), 12u);
  EXPECT_EQ(plan[4].folder, "maze__utility__2");

  // The output folder and the order of seeds do not change a run; its options do.
  StudySpec elsewhere = spec_with(dir.str(), "");
  elsewhere.out = "/somewhere/else";
  EXPECT_EQ(plan_missions(elsewhere)[4].id, plan[4].id);
  const auto reordered =
      plan_missions(parse_study("name: p\nworlds:\n  - {name: plan.pgm, resolution: 0.1}\n  - "
                                "{name: maze}\nstrategies: [utility, nearest]\n"
                                "seeds: [3, 2, 1]\n",
                                "p.yaml", dir.str()));
  EXPECT_EQ(reordered[0].id, plan[11].id);  // plan.pgm, utility, seed 3 either way
  const auto longer = plan_missions(spec_with(dir.str(), "time_limit: 61\n"));
  for (std::size_t i = 0; i < plan.size(); ++i) EXPECT_NE(longer[i].id, plan[i].id);

  // A changed world file changes the ids of its missions only.
  std::ofstream(dir.str() + "/plan.pgm") << "P2\n2 1\n255\n0 255\n";
  const auto edited = plan_missions(spec_with(dir.str(), ""));
  for (std::size_t i = 0; i < plan.size(); ++i) {
    if (plan[i].run.world == 0)
      EXPECT_EQ(edited[i].id, plan[i].id);
    else
      EXPECT_NE(edited[i].id, plan[i].id);
  }
}

TEST(StudyPlan, CheckRefusesAChangedStudy) {
  const slam::test::TempPath dir;
  std::filesystem::create_directories(dir.str());
  std::ofstream(dir.str() + "/plan.pgm") << "P2\n2 1\n255\n255 0\n";
  const StudySpec spec = spec_with(dir.str(), "");
  EXPECT_THROW(check_plan(spec, plan_missions(spec)), slam::ParseError);  // not written yet
  write_plan(spec, plan_missions(spec));
  EXPECT_NO_THROW(check_plan(spec, plan_missions(spec)));
  const StudySpec changed = spec_with(dir.str(), "coverage_goal: 0.9\n");
  try {
    check_plan(changed, plan_missions(changed));
    FAIL();
  } catch (const slam::ParseError& e) {
    EXPECT_EQ(e.line(), 2u);  // the first mission's row
    EXPECT_NE(std::string(e.what()).find(plan_missions(changed)[0].id), std::string::npos) << e.what();
  }
  StudySpec fewer = spec;
  fewer.seeds = {1, 2};
  EXPECT_THROW(check_plan(fewer, plan_missions(fewer)), slam::ParseError);
  std::filesystem::remove(dir.str() + "/plan.pgm");
  try {
    plan_missions(spec);
    FAIL();
  } catch (const slam::ParseError& e) {
    EXPECT_EQ(e.line(), 5u);
    EXPECT_NE(e.value().find("plan.pgm"), std::string::npos);
  }
}

TEST(PairedTTest, HandComputedExample) {
  // d = {1, 2, 3, 6}: mean 3, s = sqrt(14/3), t = 3 / (s / 2) = 2.7775, df 3, p = 0.0690.
  const WelchResult r = paired_t_test({11, 12, 13, 16}, {10, 10, 10, 10});
  ASSERT_TRUE(r.defined);
  EXPECT_NEAR(r.mean_difference, 3.0, 1e-12);
  EXPECT_NEAR(r.t, 2.77746, 1e-4);
  EXPECT_DOUBLE_EQ(r.df, 3.0);
  EXPECT_NEAR(r.p, 0.069, 2e-3);
  EXPECT_FALSE(paired_t_test({1}, {2}).defined);
  EXPECT_FALSE(paired_t_test({1, 2}, {0, 1}).defined);  // constant difference
  EXPECT_FALSE(paired_t_test({1, 2, 3}, {0, 1}).defined);
}

TEST(StudySlurm, ScriptsRunTheShardsAndMergeAfterThem) {
  SlurmJobOptions o;
  o.binary = "/opt/my lookahead/lookahead";
  o.study = "/shared/s.yaml";
  o.workdir = "/shared";
  o.out = "/shared/out/s";
  o.name = "lookahead-s";
  o.shards = 40;
  o.max_parallel = 8;
  o.cpus_per_task = 4;
  o.partition = "cpu";
  o.time = "1:00:00";
  const std::string array = slurm_array_script(o);
  for (const char* line : {"#SBATCH --array=0-39%8\n", "#SBATCH --cpus-per-task=4\n", "#SBATCH --partition=cpu\n",
                           "#SBATCH --time=1:00:00\n", "#SBATCH --chdir=/shared\n",
                           "#SBATCH --output=/shared/out/s/slurm/logs/array_%A_%a.log\n",
                           "exec '/opt/my lookahead/lookahead' study run '/shared/s.yaml' --shard "
                           "\"${SLURM_ARRAY_TASK_ID}/40\" --jobs 4\n"})
    EXPECT_NE(array.find(line), std::string::npos) << line << array;
  EXPECT_NE(slurm_merge_script(o).find("study merge '/shared/s.yaml'"), std::string::npos);
  EXPECT_NE(slurm_submit_script(o).find("--dependency=afterany:\"$array\""), std::string::npos);
  EXPECT_EQ(shell_quote("it's"), "'it'\\''s'");
}

}  // namespace
}  // namespace lookahead::exploration
