// SPDX-License-Identifier: MIT
// Studies: the statistics against hand-computed and closed-form values, the study file's
// errors, and a tiny study that writes its tables and resumes without redoing finished runs.
#include "lookahead/exploration/study.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include "lookahead/exploration/study_report.hpp"
#include "lookahead/exploration/study_statistics.hpp"
#include "lookahead/planner/ompl_logging.hpp"
#include "lookahead/slam/io/parse_error.hpp"
#include "temp_file.hpp"

namespace lookahead::exploration {
namespace {

namespace fs = std::filesystem;

TEST(StudentT, TwoSidedPValues) {
  EXPECT_NEAR(student_t_two_sided_p(2.0, 10), 0.0733880348, 1e-9);  // tables: 0.0734
  EXPECT_NEAR(student_t_two_sided_p(-2.0, 10), 0.0733880348, 1e-9);
  EXPECT_NEAR(student_t_two_sided_p(1.0, 1), 0.5, 1e-12);  // Cauchy: 1 - 2 atan(t) / pi
  EXPECT_NEAR(student_t_two_sided_p(3.0, 1), 1 - 2 * std::atan(3.0) / M_PI, 1e-12);
  EXPECT_NEAR(student_t_two_sided_p(2.0, 2), 1 - 2 / std::sqrt(6.0),
              1e-12);                                             // 1 - t / sqrt(t^2 + 2)
  EXPECT_NEAR(student_t_two_sided_p(1.959964, 1e7), 0.05, 1e-5);  // the normal limit
  EXPECT_DOUBLE_EQ(student_t_two_sided_p(0.0, 7), 1.0);
}

TEST(StudentT, QuantilesMatchTables) {
  EXPECT_NEAR(student_t_quantile(0.975, 4), 2.776445, 1e-6);
  EXPECT_NEAR(student_t_quantile(0.975, 19), 2.093024, 1e-6);
  EXPECT_NEAR(student_t_quantile(0.025, 19), -2.093024, 1e-6);
  EXPECT_NEAR(student_t_quantile(0.95, 1), 6.313752, 1e-6);
  EXPECT_THROW((void)student_t_quantile(1.0, 3), std::invalid_argument);
  EXPECT_THROW((void)student_t_quantile(0.9, 0), std::invalid_argument);
}

// a: mean 3, variance 2.5; b: mean 6, variance 10. se^2 = 2.5/5 + 10/5 = 2.5, so
// t = -3 / sqrt(2.5) = -1.8974 and df = 2.5^2 / (0.5^2/4 + 2^2/4) = 6.25 / 1.0625 = 5.8824.
// p = 0.10753 by numerical integration of the t density (independent of the beta function).
TEST(Welch, HandComputedExample) {
  const WelchResult r = welch_t_test({1, 2, 3, 4, 5}, {2, 4, 6, 8, 10});
  ASSERT_TRUE(r.defined);
  EXPECT_NEAR(r.t, -3 / std::sqrt(2.5), 1e-12);
  EXPECT_NEAR(r.df, 6.25 / 1.0625, 1e-12);
  EXPECT_NEAR(r.p, 0.107531195, 1e-7);
  EXPECT_DOUBLE_EQ(r.mean_difference, -3.0);
  // Unequal sizes: means 20.5 / 24.2, variances 2.276 / 3.5667 -> t -3.2819, df 5.4984, p 0.019057.
  const WelchResult u = welch_t_test({19.1, 21.3, 20.2, 22.8, 18.7, 20.9}, {23.4, 25.1, 22.0, 26.3});
  EXPECT_NEAR(u.t, -3.28192724, 1e-7);
  EXPECT_NEAR(u.df, 5.49840209, 1e-7);
  EXPECT_NEAR(u.p, 0.0190572818, 1e-8);
}

TEST(Welch, UndefinedCasesSayWhy) {
  EXPECT_FALSE(welch_t_test({1}, {2, 3}).defined);
  const WelchResult r = welch_t_test({4, 4}, {5, 5});
  EXPECT_FALSE(r.defined);
  EXPECT_FALSE(r.why.empty());
  EXPECT_TRUE(welch_t_test({4, 4}, {5, 6}).defined);  // one sample may be constant
  EXPECT_NEAR(sample_std({2, 4, 4, 4, 5, 5, 7, 9}), std::sqrt(32.0 / 7), 1e-12);
}

TEST(StudyReport, MeanCoverageCurveInterpolatesAndHolds) {
  const std::vector<CoverageSample> a{{0, 0, 0.0}, {10, 1, 1.0}}, b{{0, 0, 0.2}, {4, 1, 0.6}};
  const std::vector<double> m = mean_coverage_curve({&a, &b}, {0, 2, 5, 10, 20});
  EXPECT_NEAR(m[0], 0.1, 1e-12);
  EXPECT_NEAR(m[1], (0.2 + 0.4) / 2, 1e-12);
  EXPECT_NEAR(m[2], (0.5 + 0.6) / 2, 1e-12);  // b ended at 4 s and keeps its coverage
  EXPECT_NEAR(m[4], (1.0 + 0.6) / 2, 1e-12);
}

StudySpec parse(const std::string& yaml) { return parse_study(yaml, "study.yaml", "/data/studies"); }

slam::ParseError study_error(const std::string& yaml) {
  try {
    parse(yaml);
  } catch (const slam::ParseError& e) {
    return e;
  }
  ADD_FAILURE() << "no error for:\n" << yaml;
  return slam::ParseError("", 0, "", "", "");
}

const std::string kHead = "name: s\nworlds:\n  - {name: office}\nstrategies: [nearest, utility]\n";

TEST(StudyConfig, ReadsWorldsSeedsAndShortcuts) {
  const StudySpec s = parse(
      "name: s\nworlds:\n  - {name: office}\n  - {name: ../plans/a.b.png, resolution: 0.2, "
      "pixel_rule: only_white, start: [1, 2, 0.5]}\n"
      "  - {name: /abs/x.yaml, label: big}\nstrategies: [nearest, utility]\nseeds: {from: 3, "
      "count: 2}\n"
      "pose_source: truth\nparticles: 7\ntime_limit: 60\nmission:\n  robot:\n    max_speed: 0.3\n");
  EXPECT_EQ(s.out, "out/study/s");
  ASSERT_EQ(s.worlds.size(), 3u);
  EXPECT_EQ(s.worlds[1].spec.name, "/data/plans/a.b.png");  // relative to the study's folder
  EXPECT_EQ(s.worlds[1].label, "a");
  EXPECT_DOUBLE_EQ(s.worlds[1].spec.image_resolution, 0.2);
  EXPECT_EQ(s.worlds[1].spec.pixel_rule, "only_white");
  ASSERT_TRUE(s.worlds[1].spec.start);
  EXPECT_DOUBLE_EQ(s.worlds[1].spec.start->y, 2);
  EXPECT_EQ(s.worlds[2].spec.name, "/abs/x.yaml");
  EXPECT_EQ(s.worlds[2].label, "big");
  EXPECT_EQ(s.seeds, (std::vector<std::uint64_t>{3, 4}));
  EXPECT_EQ(s.mission.pose_source, PoseSource::kTruth);
  EXPECT_EQ(s.mission.slam.particles, 7);
  EXPECT_DOUBLE_EQ(s.mission.time_limit, 60);
  EXPECT_DOUBLE_EQ(s.mission.follower.max_linear_speed, 0.3);  // harmonized from the block
  const std::vector<StudyRun> runs = plan_runs(s);
  ASSERT_EQ(runs.size(), 12u);
  EXPECT_EQ(run_id(s, runs[5]), "a__nearest__4");
  EXPECT_EQ(run_options(s, runs[5]).slam.threads, 1);
  EXPECT_EQ(run_options(s, runs[5]).seed, 4u);
}

TEST(StudyConfig, MalformedFilesNameTheLine) {
  slam::ParseError e = study_error(kHead + "seeds: [1, 2]\ntime_limt: 60\n");
  EXPECT_EQ(e.file(), "study.yaml");
  EXPECT_EQ(e.line(), 6u);
  EXPECT_EQ(e.field(), "time_limt");
  e = study_error(kHead + "seeds: [1, x]\n");
  EXPECT_EQ(e.line(), 5u);
  EXPECT_EQ(e.value(), "x");
  e = study_error("name: s\nworlds:\n  - {name: office, resoluton: 2}\nstrategies: [nearest]\nseeds: [1]\n");
  EXPECT_EQ(e.line(), 3u);
  EXPECT_EQ(e.field(), "worlds.resoluton");
  EXPECT_EQ(study_error(kHead + "seeds: [1]\npose_source: gps\n").line(), 6u);
  e = study_error(
      "name: s\nworlds:\n  - {name: a.png, resolution: 0.05}\n  - name: b.png\n    pixel_rule: grey\n"
      "    resolution: 0.1\nstrategies: "
      "[nearest]\nseeds: [1]\n");
  EXPECT_EQ(e.line(), 5u);
  EXPECT_EQ(e.value(), "grey");
  EXPECT_GE(study_error(kHead + "seeds: [1]\nname: [\n").line(),
            6u);  // YAML syntax: where it is noticed
  EXPECT_EQ(study_error("name: s\nworlds: []\nstrategies: [nearest]\nseeds: [1]\n").line(), 2u);
  EXPECT_EQ(study_error("name: s\nworlds:\n  - {name: office}\nstrategies: [nearest, zigzag]\nseeds: [1]\n").line(),
            4u);
  e = study_error(kHead + "seeds: [1]\nmission:\n  robot:\n    radius: 0.2\n  slam:\n    filter:\n      partcles: 3\n");
  EXPECT_EQ(e.line(), 11u);  // the slam section inside the mission block keeps the study's lines
  EXPECT_EQ(e.field(), "filter.partcles");
  e = study_error(kHead + "seeds: [1]\ntime_limit: 60\nmission:\n  mission:\n    time_limit: 90\n");
  EXPECT_EQ(e.line(), 9u);  // set twice: neither silently wins
  EXPECT_EQ(study_error(kHead + "seeds: [1]\nmission:\n  mission:\n    seed: 4\n").line(), 8u);
}

std::size_t data_rows(const std::string& csv_path) {
  std::ifstream in(csv_path);
  std::size_t rows = 0;
  for (std::string line; std::getline(in, line);) rows += line.empty() ? 0 : 1;
  return rows == 0 ? 0 : rows - 1;
}

// The office for 60 simulated seconds, 2 strategies x 2 seeds at the true pose: enough to
// exercise every output; the missions end by their time limit.
TEST(Study, TinyStudyWritesTablesAndResumes) {
  planner::set_ompl_log_level(planner::OmplLogLevel::kWarn);
  const slam::test::TempPath dir;
  fs::create_directories(dir.str());
  std::ofstream(dir.str() + "/tiny.yaml") << "name: tiny\nout: " << dir.str() << "/out\nworlds:\n  - {name: office}\n"
                                          << "strategies: [nearest, utility]\nseeds: [1, 2]\npose_source: truth\n"
                                          << "time_limit: 60\n";
  const StudySpec spec = load_study(dir.str() + "/tiny.yaml");
  std::size_t calls = 0;
  const StudyResult first = run_study(spec, [&](const StudyProgress& p) {
    ++calls;
    EXPECT_EQ(p.total, 4u);
  });
  EXPECT_EQ(first.executed, 4u);
  EXPECT_EQ(calls, 5u);  // once before the first run, then after each
  write_study_outputs(spec, first);
  const std::string out = spec.out;
  EXPECT_EQ(data_rows(out + "/results.csv"), 4u);
  for (const char* f : {"/summary.md", "/coverage_office.png", "/time_to_95.png", "/runs/office__utility__2/map.png"}) {
    EXPECT_TRUE(fs::exists(out + f)) << f;
  }
  for (const StudyRunResult& r : first.runs) {
    EXPECT_EQ(r.summary.status, "time_limit");
    EXPECT_FALSE(r.curve.empty());
  }

  const auto stamp = fs::last_write_time(out + "/runs/office__nearest__1/run.json");
  const StudyResult again = run_study(spec);
  EXPECT_EQ(again.executed, 0u);
  EXPECT_EQ(again.reused, 4u);
  EXPECT_EQ(study_results_csv(spec, again), study_results_csv(spec, first));

  fs::remove(out + "/runs/office__utility__1/run.json");
  const StudyResult third = run_study(spec);
  EXPECT_EQ(third.executed, 1u);
  EXPECT_FALSE(third.runs[2].reused);  // office, utility, seed 1
  EXPECT_EQ(fs::last_write_time(out + "/runs/office__nearest__1/run.json"), stamp);
  EXPECT_DOUBLE_EQ(third.runs[2].summary.path_length,
                   first.runs[2].summary.path_length);  // same seed, same run

  std::ofstream(out + "/runs/office__nearest__2/run.json") << "{\"world\": \"off";  // cut short
  EXPECT_EQ(run_study(spec).executed, 1u);
  StudySpec longer = spec;  // a changed option or world redoes every run it changes
  longer.mission.time_limit = 61;
  const std::string run0 = out + "/runs/office__nearest__1";
  EXPECT_FALSE(read_finished_run(run0, run_config_text(longer, plan_runs(longer)[0])));
  StudySpec other_office = spec;
  other_office.worlds[0].spec.seed = 2;
  EXPECT_FALSE(read_finished_run(run0, run_config_text(other_office, plan_runs(other_office)[0])));
  EXPECT_TRUE(read_finished_run(run0, run_config_text(spec, plan_runs(spec)[0])));

  // A run of another build (another commit in run.json's provenance) is run again.
  std::string json;
  {
    std::ifstream in(run0 + "/run.json");
    json.assign(std::istreambuf_iterator<char>(in), {});
  }
  const std::string commit = "\"commit\": \"";
  const std::size_t at = json.find(commit);
  ASSERT_NE(at, std::string::npos);
  json.insert(at + commit.size(), "another-build-");
  std::ofstream(run0 + "/run.json") << json;
  EXPECT_FALSE(read_finished_run(run0, run_config_text(spec, plan_runs(spec)[0])));
  EXPECT_EQ(run_study(spec).executed, 1u);
}

}  // namespace
}  // namespace lookahead::exploration
