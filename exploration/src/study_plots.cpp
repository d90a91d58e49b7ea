// SPDX-License-Identifier: MIT
// The study's pictures (declared in study_report.hpp): mean coverage curves per world and
// the time-to-95 % bar chart.
#include <algorithm>

#include "lookahead/exploration/line_plot.hpp"
#include "lookahead/exploration/study_bar_plot.hpp"
#include "lookahead/exploration/study_report.hpp"
#include "lookahead/exploration/study_statistics.hpp"

namespace lookahead::exploration {
namespace {

constexpr std::size_t kGridPoints = 400;  // plenty for an 800 px wide plot

void write_coverage_plot(const std::string& path, const StudySpec& spec, const StudyResult& result, std::size_t w) {
  double end = 0.0;  // the grid spans the longest run of this world
  for (const std::string& strategy : spec.strategies) {
    for (const StudyRunResult* r : runs_of(spec, result, w, strategy)) {
      if (!r->curve.empty()) end = std::max(end, r->curve.back().time);
    }
  }
  std::vector<double> grid(kGridPoints);
  for (std::size_t i = 0; i < kGridPoints; ++i) grid[i] = end * static_cast<double>(i) / (kGridPoints - 1);
  std::vector<PlotSeries> series;
  for (std::size_t s = 0; s < spec.strategies.size(); ++s) {
    std::vector<const std::vector<CoverageSample>*> curves;
    for (const StudyRunResult* r : runs_of(spec, result, w, spec.strategies[s])) curves.push_back(&r->curve);
    series.push_back({spec.strategies[s] + " (" + std::to_string(curves.size()) + " runs)", grid,
                      mean_coverage_curve(curves, grid), series_colour(s)});
  }
  write_line_plot(path, series,
                  {spec.worlds[w].label + ": mean coverage of the reachable free area", "simulated time [s]",
                   "coverage", 800, 450, 0.0, 1.0});
}

void write_time_to_95_plot(const std::string& path, const StudySpec& spec, const StudyResult& result) {
  BarChart chart;
  chart.title = "time to 95 % coverage: mean +- std over the n runs that reached it";
  chart.y_label = "simulated time [s]";
  chart.series = spec.strategies;
  chart.width = std::max(900, 120 * static_cast<int>(spec.worlds.size() * spec.strategies.size()) / 2 + 300);
  for (std::size_t w = 0; w < spec.worlds.size(); ++w) {
    chart.groups.push_back(spec.worlds[w].label);
    std::vector<Bar> bars;
    for (const std::string& strategy : spec.strategies) {
      std::vector<double> times;
      for (const StudyRunResult* r : runs_of(spec, result, w, strategy)) {
        if (r->summary.milestones[1].reached) times.push_back(r->summary.milestones[1].time);
      }
      bars.push_back({!times.empty(), mean(times), sample_std(times), static_cast<int>(times.size())});
    }
    chart.bars.push_back(bars);
  }
  write_bar_chart(path, chart);
}

}  // namespace

void write_study_plots(const std::string& dir, const StudySpec& spec, const StudyResult& result) {
  for (std::size_t w = 0; w < spec.worlds.size(); ++w) {
    write_coverage_plot(dir + "/coverage_" + spec.worlds[w].label + ".png", spec, result, w);
  }
  write_time_to_95_plot(dir + "/time_to_95.png", spec, result);
}

}  // namespace lookahead::exploration
