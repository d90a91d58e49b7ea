// SPDX-License-Identifier: MIT
// The study tables on a hand-made result: the overall line and status counts, the share of
// the plan, the paired comparison on the seed, runs not finished, and report.html escaping.
#include "lookahead/exploration/study_tables.hpp"

#include <gtest/gtest.h>

#include "lookahead/exploration/study_html.hpp"
#include "lookahead/exploration/study_report.hpp"

namespace lookahead::exploration {
namespace {

// 1 world x {nearest, utility} x seeds {1, 2, 3}: nearest reaches 95 % at 100, 110, 130 s; utility
// at 90, 100, - (seed 3 trapped); nearest seed 2 is not finished.
StudyResult hand_made(const StudySpec& spec) {
  StudyResult result;
  const std::vector<StudyRun> plan = plan_runs(spec);
  result.runs.resize(plan.size());
  const double times[2][3] = {{100, 110, 130}, {90, 100, -1}};
  for (std::size_t i = 0; i < plan.size(); ++i) {
    StudyRunResult& r = result.runs[i];
    const int s = plan[i].strategy == "nearest" ? 0 : 1;
    const double t = times[s][plan[i].seed - 1];
    r.finished = !(s == 0 && plan[i].seed == 2);
    r.summary.seed = plan[i].seed;
    r.summary.status = t > 0 ? "coverage_reached" : "trapped";
    r.summary.milestones[1] = {0.95, t > 0, t, t / 10};
    r.summary.reachable_area_m2 = 10;
    r.plan_free_area_m2 = 40;
    r.summary.statistics.backtracks = s;
  }
  return result;
}

TEST(StudyTables, OverallStatusAndPairs) {
  const StudySpec spec =
      parse_study("name: t\nworlds: [{name: maze}]\nstrategies: [nearest, utility]\nseeds: [1, 2, 3]\n", "t.yaml", ".");
  const StudyResult result = hand_made(spec);
  EXPECT_EQ(overall_line(spec, result),
            "4 of 5 missions reached the coverage goal of 0.95 (nearest 2/2, utility 2/3); 1 of 6 "
            "planned "
            "missions are not finished.");
  const StudyTable status = status_table(spec, result);
  ASSERT_EQ(status.rows.size(), 3u);
  EXPECT_EQ(status.rows[2], (std::vector<std::string>{"all", "5", "4", "0", "1", "0", "0"}));
  const StudyTable table = strategy_table(spec, result, 0);
  EXPECT_EQ(table.rows[0][1], "2");               // nearest: the unfinished run is not counted
  EXPECT_EQ(table.rows[0][8], "0.250 +- 0.000");  // reachable share of the plan
  EXPECT_EQ(table.rows[1][2], "2/3 (67 %)");
  // Pairs on seeds both reached: seed 1 only (nearest seed 2 missing, utility seed 3 trapped).
  const StudyTable paired = paired_table(spec, result, 0);
  ASSERT_EQ(paired.rows.size(), 1u);
  EXPECT_EQ(paired.rows[0][2], "1");
  EXPECT_EQ(paired.rows[0][4], "1");  // utility faster
  EXPECT_EQ(paired.rows[0][5], "n/a: fewer than 2 pairs");
  EXPECT_EQ(missing_runs(spec, result), std::vector<std::string>{"maze__nearest__2"});
  const std::string csv = study_results_csv(spec, result);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 6);  // header + 5 finished
  const std::string md = to_markdown(status);
  EXPECT_EQ(md.substr(0, md.find('\n')),
            "| strategy | missions | coverage_reached | done | trapped | time_limit | collision |");
}

TEST(StudyHtml, EscapesAndLinksEveryMap) {
  EXPECT_EQ(html_escape("<a href=\"x\">&'"), "&lt;a href=&quot;x&quot;&gt;&amp;&#39;");
  const StudySpec spec =
      parse_study("name: t\nworlds: [{name: maze}]\nstrategies: [nearest, utility]\nseeds: [1, 2, 3]\n", "t.yaml", ".");
  const std::string html = study_report_html(spec, hand_made(spec));
  std::size_t maps = 0;
  for (std::size_t at = html.find("<a href=\"runs/"); at != std::string::npos;
       at = html.find("<a href=\"runs/", at + 1))
    ++maps;
  EXPECT_EQ(maps, 5u);
  EXPECT_NE(html.find("<li>maze__nearest__2</li>"), std::string::npos);  // listed as not finished
  EXPECT_EQ(html.find("http"), std::string::npos);                       // nothing from the network
}

}  // namespace
}  // namespace lookahead::exploration
