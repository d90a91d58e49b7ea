// SPDX-License-Identifier: MIT
#include "lookahead/exploration/study_report.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <fstream>

#include "lookahead/exploration/mission_config.hpp"
#include "lookahead/exploration/study_statistics.hpp"
#include "lookahead/slam/io/parse_error.hpp"

namespace lookahead::exploration {
namespace {

constexpr std::size_t k95 = 1;  // index of the 95 % milestone in MissionSummary::milestones

std::string milestone_cells(const Milestone& m) {
  return m.reached ? fmt::format("{:.2f},{:.3f}", m.time, m.path_length) : ",";
}

std::string mean_std(const std::vector<double>& v, int decimals) {
  if (v.empty()) return "-";
  if (v.size() == 1) return fmt::format("{:.{}f}", v[0], decimals);
  return fmt::format("{:.{}f} +- {:.{}f}", mean(v), decimals, sample_std(v), decimals);
}

// Times and path lengths to 95 % of the runs that got there.
std::pair<std::vector<double>, std::vector<double>> to_95(
    const std::vector<const StudyRunResult*>& runs) {
  std::pair<std::vector<double>, std::vector<double>> out;
  for (const StudyRunResult* r : runs) {
    const Milestone& m = r->summary.milestones[k95];
    if (!m.reached) continue;
    out.first.push_back(m.time);
    out.second.push_back(m.path_length);
  }
  return out;
}

std::string strategy_table(const StudySpec& spec, const StudyResult& result, std::size_t w) {
  std::string md =
      "| strategy | runs | reached 95 % | time to 95 % [s] | path to 95 % [m] | collisions | final "
      "coverage |\n"
      "|---|---|---|---|---|---|---|\n";
  for (const std::string& strategy : spec.strategies) {
    const auto runs = runs_of(spec, result, w, strategy);
    const auto [times, paths] = to_95(runs);
    int collisions = 0;
    std::vector<double> coverage;
    for (const StudyRunResult* r : runs) {
      collisions += r->summary.statistics.collisions;
      coverage.push_back(r->summary.coverage);
    }
    md += fmt::format(
        "| {} | {} | {}/{} ({:.0f} %) | {} | {} | {} | {} |\n", strategy, runs.size(), times.size(),
        runs.size(),
        runs.empty() ? 0.0
                     : 100.0 * static_cast<double>(times.size()) / static_cast<double>(runs.size()),
        mean_std(times, 1), mean_std(paths, 1), collisions, mean_std(coverage, 3));
  }
  return md;
}

std::string welch_row(const std::string& a, const std::string& b, const char* measure,
                      const std::vector<double>& va, const std::vector<double>& vb) {
  const WelchResult r = welch_t_test(va, vb);
  if (!r.defined) return fmt::format("| {} | {} | {} | n/a: {} | | | |\n", a, b, measure, r.why);
  return fmt::format("| {} | {} | {} | {:.2f} | {:.3f} | {:.2f} | {:.4f} |\n", a, b, measure,
                     r.mean_difference, r.t, r.df, r.p);
}

std::string welch_table(const StudySpec& spec, const StudyResult& result, std::size_t w) {
  if (spec.strategies.size() < 2) return "";
  std::string md =
      "Welch's t-test (two-sided, unequal variances; only runs that reached 95 %):\n\n"
      "| a | b | measure | mean a - b | t | df | p |\n|---|---|---|---|---|---|---|\n";
  for (std::size_t i = 0; i < spec.strategies.size(); ++i) {
    for (std::size_t j = i + 1; j < spec.strategies.size(); ++j) {
      const auto [ta, pa] = to_95(runs_of(spec, result, w, spec.strategies[i]));
      const auto [tb, pb] = to_95(runs_of(spec, result, w, spec.strategies[j]));
      md += welch_row(spec.strategies[i], spec.strategies[j], "time to 95 % [s]", ta, tb);
      md += welch_row(spec.strategies[i], spec.strategies[j], "path to 95 % [m]", pa, pb);
    }
  }
  return md + "\n";
}

}  // namespace

std::vector<const StudyRunResult*> runs_of(const StudySpec& spec, const StudyResult& result,
                                           std::size_t world, const std::string& strategy) {
  std::vector<const StudyRunResult*> out;
  const std::vector<StudyRun> plan = plan_runs(spec);
  for (std::size_t i = 0; i < plan.size() && i < result.runs.size(); ++i) {
    if (plan[i].world == world && plan[i].strategy == strategy) out.push_back(&result.runs[i]);
  }
  return out;
}

std::string study_results_csv(const StudySpec& spec, const StudyResult& result) {
  std::string csv =
      "world,strategy,seed,status,simulated_time_s,path_length_m,time_to_90_s,path_to_90_m,time_to_"
      "95_s,"
      "path_to_95_m,time_to_99_s,path_to_99_m,coverage,map_precision,map_recall,collisions,wall_"
      "time_s,"
      "real_time_factor\n";
  const std::vector<StudyRun> plan = plan_runs(spec);
  for (std::size_t i = 0; i < plan.size() && i < result.runs.size(); ++i) {
    const MissionSummary& s = result.runs[i].summary;
    csv += fmt::format("{},{},{},{},{:.2f},{:.3f},{},{},{},{:.4f},{:.4f},{:.4f},{},{:.2f},{:.1f}\n",
                       spec.worlds[plan[i].world].label, plan[i].strategy, plan[i].seed, s.status,
                       s.simulated_time, s.path_length, milestone_cells(s.milestones[0]),
                       milestone_cells(s.milestones[1]), milestone_cells(s.milestones[2]),
                       s.coverage, s.quality.precision, s.quality.recall, s.statistics.collisions,
                       s.wall_time, s.real_time_factor);
  }
  return csv;
}

std::string study_summary_markdown(const StudySpec& spec, const StudyResult& result) {
  const MissionOptions& o = spec.mission;
  std::string md = fmt::format("# Study {}\n\n", spec.name);
  md += fmt::format(
      "{} runs: {} world(s) x {} strateg{} x {} seed(s), from {}. Pose source {}{}, time limit "
      "{:g} s "
      "(simulated), coverage goal {:g}, robot top speed {:g} m/s.\n\n",
      result.runs.size(), spec.worlds.size(), spec.strategies.size(),
      spec.strategies.size() == 1 ? "y" : "ies", spec.seeds.size(), spec.source,
      pose_source_name(o.pose_source),
      o.pose_source == PoseSource::kSlam ? fmt::format(" ({} particles)", o.slam.particles) : "",
      o.time_limit, o.coverage_goal, o.robot.max_speed);
  md +=
      "Times are simulated seconds; \"to 95 %\" is until 95 % of the reachable free area of the "
      "true world "
      "was mapped. Means +- sample standard deviations are over the runs that reached 95 %, so "
      "read them "
      "together with the share that did. Collisions are summed over the runs.\n\n";
  for (std::size_t w = 0; w < spec.worlds.size(); ++w) {
    const std::string& label = spec.worlds[w].label;
    md += fmt::format("## {}\n\n{}\n{}![coverage of {}](coverage_{}.png)\n\n", label,
                      strategy_table(spec, result, w), welch_table(spec, result, w), label, label);
  }
  return md + "## Time to 95 % coverage\n\n![time to 95 %](time_to_95.png)\n";
}

std::vector<double> mean_coverage_curve(
    const std::vector<const std::vector<CoverageSample>*>& curves,
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
  write(spec.out + "/summary.md", study_summary_markdown(spec, result));
  write_study_plots(spec.out, spec, result);
}

}  // namespace lookahead::exploration
