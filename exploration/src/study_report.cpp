// SPDX-License-Identifier: MIT
#include "lookahead/exploration/study_report.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <fstream>

#include "lookahead/exploration/mission_config.hpp"
#include "lookahead/exploration/study_html.hpp"
#include "lookahead/exploration/study_plan.hpp"
#include "lookahead/exploration/study_tables.hpp"
#include "lookahead/slam/io/parse_error.hpp"

namespace lookahead::exploration {
namespace {

std::string milestone_cells(const Milestone& m) {
  return m.reached ? fmt::format("{:.2f},{:.3f}", m.time, m.path_length) : ",";
}

}  // namespace

std::vector<const StudyRunResult*> runs_of(const StudySpec& spec, const StudyResult& result, std::size_t world,
                                           const std::string& strategy) {
  std::vector<const StudyRunResult*> out;
  const std::vector<StudyRun> plan = plan_runs(spec);
  for (std::size_t i = 0; i < plan.size() && i < result.runs.size(); ++i) {
    if (plan[i].world == world && plan[i].strategy == strategy && result.runs[i].finished)
      out.push_back(&result.runs[i]);
  }
  return out;
}

std::string study_results_csv(const StudySpec& spec, const StudyResult& result) {
  std::string csv =
      "world,strategy,seed,status,simulated_time_s,path_length_m,time_to_90_s,path_to_90_m,"
      "time_to_95_s,path_to_95_m,time_to_99_s,path_to_99_m,coverage,map_precision,map_recall,"
      "collisions,reachable_area_m2,plan_free_area_m2,reachable_share_of_plan,stuck_goals,"
      "backtracks,coverage_with_predictions,mission_id,wall_time_s,real_time_factor\n";
  const std::vector<StudyRun> plan = plan_runs(spec);
  for (std::size_t i = 0; i < plan.size() && i < result.runs.size(); ++i) {
    const StudyRunResult& r = result.runs[i];
    if (!r.finished) continue;
    const MissionSummary& s = r.summary;
    csv += fmt::format(
        "{},{},{},{},{:.2f},{:.3f},{},{},{},{:.4f},{:.4f},{:.4f},{},{:.2f},{:.2f},{:.4f},{},{},{},{"
        "},"
        "{:.2f},{:.1f}\n",
        spec.worlds[plan[i].world].label, plan[i].strategy, plan[i].seed, s.status, s.simulated_time, s.path_length,
        milestone_cells(s.milestones[0]), milestone_cells(s.milestones[1]), milestone_cells(s.milestones[2]),
        s.coverage, s.quality.precision, s.quality.recall, s.statistics.collisions, s.reachable_area_m2,
        r.plan_free_area_m2, r.plan_free_area_m2 > 0 ? s.reachable_area_m2 / r.plan_free_area_m2 : 0.0,
        s.statistics.stuck_goals, s.statistics.backtracks,
        r.predicted_coverage >= 0 ? fmt::format("{:.4f}", r.predicted_coverage) : "", r.mission_id, s.wall_time,
        s.real_time_factor);
  }
  return csv;
}

std::string study_overall_csv(const StudySpec& spec, const StudyResult& result) {
  const StudyTable t = status_table(spec, result);
  std::string csv = t.header[0];  // coverage_reached: the missions that reached the goal
  for (std::size_t c = 1; c < t.header.size(); ++c) csv += "," + t.header[c];
  csv += ",not_finished\n";
  const std::size_t missing = result.runs.size() - result.finished();
  for (const auto& row : t.rows) {
    csv += row[0];
    for (std::size_t c = 1; c < row.size(); ++c) csv += "," + row[c];
    csv += "," + (row[0] == "all" ? std::to_string(missing) : std::string()) + "\n";
  }
  return csv;
}

std::vector<std::string> missing_runs(const StudySpec& spec, const StudyResult& result) {
  std::vector<std::string> out;
  const std::vector<StudyRun> plan = plan_runs(spec);
  for (std::size_t i = 0; i < plan.size() && i < result.runs.size(); ++i) {
    if (!result.runs[i].finished) out.push_back(run_id(spec, plan[i]));
  }
  return out;
}

std::string study_summary_markdown(const StudySpec& spec, const StudyResult& result) {
  const MissionOptions& o = spec.mission;
  std::string md = fmt::format("# Study {}\n\n", spec.name);
  md += fmt::format(
      "{} missions: {} world(s) x {} strateg{} x {} seed(s), from {}. Pose source {}{}, time limit "
      "{:g} s "
      "(simulated), coverage goal {:g}, robot top speed {:g} m/s.\n\n",
      result.runs.size(), spec.worlds.size(), spec.strategies.size(), spec.strategies.size() == 1 ? "y" : "ies",
      spec.seeds.size(), spec.source, pose_source_name(o.pose_source),
      o.pose_source == PoseSource::kSlam ? fmt::format(" ({} particles)", o.slam.particles) : "", o.time_limit,
      o.coverage_goal, o.robot.max_speed);
  md +=
      "Times are simulated seconds; \"to 95 %\" is until 95 % of the reachable free area of the "
      "true world "
      "was mapped. Means +- sample standard deviations are over the runs that reached 95 %, so "
      "read them "
      "together with the share that did. Collisions are summed over the runs.\n\n";
  md += "**" + overall_line(spec, result) + "**\n\n" + to_markdown(status_table(spec, result)) + "\n";
  if (const auto missing = missing_runs(spec, result); !missing.empty()) {
    md += fmt::format("Not finished ({}, listed in missing.txt):", missing.size());
    for (std::size_t i = 0; i < missing.size() && i < 20; ++i) md += " " + missing[i];
    md += missing.size() > 20 ? " ...\n\n" : "\n\n";
  }
  md +=
      "Reachable area: the free area connected to the start; its share of the plan is against "
      "every free cell of the world, so a start closed into a small pocket shows here and not "
      "as a perfect run.\n\n";
  for (std::size_t w = 0; w < spec.worlds.size(); ++w) {
    const std::string& label = spec.worlds[w].label;
    md += fmt::format("## {}\n\n{}\n", label, to_markdown(strategy_table(spec, result, w)));
    if (spec.strategies.size() > 1) {
      md += "Welch's t-test (two-sided, unequal variances; only runs that reached 95 %):\n\n" +
            to_markdown(welch_table(spec, result, w)) +
            "\nPaired on the seed (runs of both strategies that reached 95 %; paired t-test on "
            "the time differences):\n\n" +
            to_markdown(paired_table(spec, result, w)) + "\n";
    }
    md += fmt::format("![coverage of {}](coverage_{}.png)\n\n", label, label);
  }
  return md + "## Time to 95 % coverage\n\n![time to 95 %](time_to_95.png)\n";
}

std::vector<double> mean_coverage_curve(const std::vector<const std::vector<CoverageSample>*>& curves,
                                        const std::vector<double>& grid) {
  std::vector<double> mean_curve(grid.size(), 0.0);
  if (curves.empty()) return mean_curve;
  for (const auto* curve : curves) {
    std::size_t k = 0;  // grid is increasing: walk each curve once
    for (std::size_t g = 0; g < grid.size(); ++g) {
      const double t = grid[g];
      while (k + 1 < curve->size() && (*curve)[k + 1].time <= t) ++k;
      double c = 0.0;
      if (curve->empty())
        c = 0.0;
      else if (t <= curve->front().time)
        c = curve->front().coverage;
      else if (k + 1 >= curve->size())
        c = curve->back().coverage;
      else {
        const CoverageSample &a = (*curve)[k], &b = (*curve)[k + 1];
        c = a.coverage + (b.coverage - a.coverage) * (t - a.time) / (b.time - a.time);
      }
      mean_curve[g] += c / static_cast<double>(curves.size());
    }
  }
  return mean_curve;
}

void write_study_outputs(const StudySpec& spec, const StudyResult& result) {
  std::filesystem::create_directories(spec.out);
  const auto write = [](const std::string& path, const std::string& text) {
    std::ofstream out(path);
    out << text;
    if (!out) throw slam::ParseError(path, 0, "", "", "cannot write");
  };
  write(spec.out + "/results.csv", study_results_csv(spec, result));
  write(spec.out + "/overall.csv", study_overall_csv(spec, result));
  write(spec.out + "/summary.md", study_summary_markdown(spec, result));
  std::string missing;
  for (const std::string& id : missing_runs(spec, result)) missing += id + "\n";
  write(spec.out + "/missing.txt", missing);
  write_study_plots(spec.out, spec, result);
  write(spec.out + "/report.html", study_report_html(spec, result));
}

}  // namespace lookahead::exploration
