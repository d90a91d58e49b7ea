// SPDX-License-Identifier: MIT
// `lookahead hybrid-sim`: the simulated experiments of HybridSLAM sec. 5 (Brooks & Bailey):
// Table 1 (success rate per filter and clutter level), the vehicle-uncertainty plots of
// Fig. 3 (compass) and Fig. 4 (no compass), NEES over time, a picture of one run, and the
// speed of one 400 m trial.
#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "hybrid_pictures.hpp"
#include "hybrid_trial_trace.hpp"
#include "lookahead/exploration/line_plot.hpp"
#include "lookahead/slam/hybrid/hybrid_config.hpp"
#include "lookahead/slam/hybrid/study.hpp"
#include "progress_bar.hpp"
#include "run_json.hpp"

namespace lookahead::app {
namespace {

using namespace slam::hybrid;

struct HybridSimArgs {
  std::string config;
  std::string out = "out/hybrid-sim";
  int trials = -1;
  int threads = -1;
  int particles = -1;
  int trial = -1;
  std::vector<std::string> filters;
  bool no_study = false;
  bool no_figures = false;
};

// Paper's Table 1, for the side-by-side text table.
const char* kPaperRows[][5] = {
    {"FASTSLAM", "0%", "0%", "0%", "0%"}, {"EKF", "79%", "76%", "72%", "30%"}, {"HYBRID", "87%", "89%", "83%", "63%"}};

HybridConfig config_from(const HybridSimArgs& a) {
  HybridConfig c;
  if (!a.config.empty()) c = load_hybrid_config(a.config);
  if (a.trials > 0) c.study.trials = a.trials;
  if (a.threads >= 0) c.study.threads = a.threads;
  if (a.particles > 0) c.filter.fastslam.particles = a.particles;
  return c;
}

struct FigureRuns {
  std::vector<FilterKind> filters;
  std::vector<TrialResult> results;
};

// One clean run of the first world with each filter, to the end (no early stop).
FigureRuns figure_runs(const HybridConfig& c, bool compass, SimulatedRun& run) {
  HybridConfig f = c;
  f.simulation.compass = compass;
  f.filter.existence.alpha = 1.0;
  f.filter.existence.beta = 0.0;
  const TrialSeeds s = trial_seeds(c.study.seed, 0, 0, c.study.worlds);
  run = simulate(f.simulation, f.filter.sensor, 1.0, 0.0, s.world, s.noise);
  FigureRuns out;
  out.filters = {FilterKind::kFastSlam, FilterKind::kEkf, FilterKind::kHybrid};
  for (FilterKind k : out.filters) {
    out.results.push_back(
        run_trial(k, run, f.filter, s.filter, {c.study.failure_sigma, c.study.failure_iterations}, false));
    spdlog::info("{} {}: {} ({:.1f} s wall for {:.0f} s simulated, {:.1f}x real time)",
                 compass ? "compass" : "no compass", filter_name(k), out.results.back().success ? "success" : "failed",
                 out.results.back().wall_s, out.results.back().simulated_s,
                 out.results.back().simulated_s / out.results.back().wall_s);
  }
  return out;
}

void plot_series(const std::string& png, const FigureRuns& runs, bool log_nees, const std::string& title, double dt) {
  std::vector<exploration::PlotSeries> series;
  double y_max = 0.0;
  for (std::size_t i = 0; i < runs.filters.size(); ++i) {
    exploration::PlotSeries s{filter_name(runs.filters[i]), {}, {}, exploration::series_colour(i)};
    const auto& values = log_nees ? runs.results[i].nees : runs.results[i].trace;
    for (std::size_t k = 0; k < values.size(); ++k) {
      s.x.push_back(static_cast<double>(k + 1));
      s.y.push_back(log_nees ? std::log10(std::max(values[k], 1e-3)) : values[k]);
      y_max = std::max(y_max, s.y.back());
    }
    series.push_back(std::move(s));
  }
  exploration::PlotOptions o;
  o.title = title;
  o.x_label = fmt::format("iteration ({} s each)", dt);
  o.y_label = log_nees ? "log10 NEES (failure above 2 = 10 std)" : "trace of vehicle covariance [m^2 + rad^2]";
  o.y_min = log_nees ? -1.0 : 0.0;
  o.y_max = log_nees ? std::min(std::max(3.0, std::ceil(y_max)), 10.0) : std::max(1e-3, y_max * 1.05);
  o.width = 1000;
  exploration::write_line_plot(png, series, o);
}

void write_world_picture(const std::string& png, const SimulatedRun& run, const TrialResult& r, const HybridConfig& c) {
  const double size = c.simulation.world_size;
  const slam::ProbabilityMap canvas = blank_map(-5.0, -5.0, size + 5.0, size + 5.0, 0.1);
  std::vector<slam::Pose2> truth;
  for (const auto& s : run.steps) truth.push_back(s.truth);
  slam::PicturePoints true_features{{}, {20, 20, 20}, "true features", 3};
  for (const auto& f : run.features) true_features.points.emplace_back(f.x(), f.y());
  std::vector<slam::PicturePoints> points = feature_layers(r.map, "HYBRID features (fused)", {200, 30, 30});
  points.push_back(true_features);
  slam::write_map_picture(png, canvas,
                          {{truth, {30, 30, 200}, "true path", 2}, {r.estimate, {200, 30, 30}, "HYBRID estimate", 1}},
                          "HybridSLAM, simulated world (clean sensor)", points);
}

nlohmann::json figures(const HybridConfig& c, const std::string& out) {
  nlohmann::json j;
  SimulatedRun run;
  const FigureRuns with = figure_runs(c, true, run);
  plot_series(out + "/fig3_trace_compass.png", with, false, "Fig. 3: vehicle uncertainty, with compass",
              c.simulation.dt);
  plot_series(out + "/nees_compass.png", with, true, "NEES over time, with compass", c.simulation.dt);
  const FigureRuns without = figure_runs(c, false, run);
  plot_series(out + "/fig4_trace.png", without, false, "Fig. 4: vehicle uncertainty, no compass", c.simulation.dt);
  plot_series(out + "/nees.png", without, true, "NEES over time, no compass", c.simulation.dt);
  write_world_picture(out + "/world.png", run, without.results[2], c);
  for (std::size_t i = 0; i < without.filters.size(); ++i) {
    const TrialResult& r = without.results[i];
    j[filter_name(without.filters[i])] = {{"success", r.success},
                                          {"failed_at", r.failed_at},
                                          {"wall_s", r.wall_s},
                                          {"simulated_s", r.simulated_s},
                                          {"x_real_time", r.simulated_s / r.wall_s},
                                          {"fusions", r.fusions},
                                          {"features", r.map.size()},
                                          {"path_m", run.path_length}};
  }
  return j;
}

std::vector<FilterKind> filters_named(const std::vector<std::string>& names) {
  std::vector<FilterKind> out;
  for (const std::string& name : names) {
    const auto* it = std::find_if(std::begin(kAllFilters), std::end(kAllFilters),
                                  [&](FilterKind k) { return filter_name(k) == name; });
    if (it == std::end(kAllFilters))
      throw std::invalid_argument("--filters: unknown filter '" + name + "' (FASTSLAM, EKF, HYBRID)");
    out.push_back(*it);
  }
  return out;
}

std::string percent(const StudyCell& c) { return fmt::format("{:.0f}%", 100.0 * c.successes / c.trials); }

void write_table(const std::string& out, const StudyResult& r, const HybridConfig& c) {
  const std::size_t levels = c.study.alphas.size();
  std::string header = "| filter |";
  std::string csv = "filter";
  for (std::size_t l = 0; l < levels; ++l) {
    header += fmt::format(" {}, {:.2f} |", c.study.alphas[l], c.study.betas[l]);
    csv += fmt::format(",alpha={} beta={}", c.study.alphas[l], c.study.betas[l]);
  }
  std::string text =
      fmt::format("Table 1: success rate over {} trials per cell ({} worlds, seed {}, {} particles)\n\n{}\n|---|{}\n",
                  c.study.trials, c.study.worlds, c.study.seed, c.filter.fastslam.particles, header, [&] {
                    std::string s;
                    for (std::size_t l = 0; l < levels; ++l) s += "---|";
                    return s;
                  }());
  csv += ",trials\n";
  for (std::size_t f = 0; f < r.filters.size(); ++f) {
    text += "| " + filter_name(r.filters[f]) + " (ours) |";
    csv += filter_name(r.filters[f]);
    for (std::size_t l = 0; l < levels; ++l) {
      const StudyCell& cell = r.cells[f * levels + l];
      text += " " + percent(cell) + " |";
      csv += fmt::format(",{:.3f}", static_cast<double>(cell.successes) / cell.trials);
    }
    csv += fmt::format(",{}\n", c.study.trials);
    text += "\n";
  }
  if (levels == 4) {
    for (const auto& row : kPaperRows)
      text += fmt::format("| {} (paper) | {} | {} | {} | {} |\n", row[0], row[1], row[2], row[3], row[4]);
  }
  std::ofstream(out + "/table1.txt") << text;
  std::ofstream(out + "/table1.csv") << csv;
  fmt::print("{}", text);
}

int run_hybrid_sim(const HybridSimArgs& a) {
  const HybridConfig c = config_from(a);
  std::filesystem::create_directories(a.out);
  if (a.trial >= 0) {
    const auto kinds =
        a.filters.empty() ? std::vector<FilterKind>{FilterKind::kEkf, FilterKind::kHybrid} : filters_named(a.filters);
    for (const std::string& line : write_trial_traces(c, a.trial, kinds, a.out)) fmt::print("{}\n", line);
    return 0;
  }
  nlohmann::json j;
  if (!a.no_figures) j["figure_runs"] = figures(c, a.out);
  if (!a.no_study) {
    const std::vector<FilterKind> filters =
        a.filters.empty() ? std::vector<FilterKind>(std::begin(kAllFilters), std::end(kAllFilters))
                          : filters_named(a.filters);
    ProgressBar bar("hybrid-sim", static_cast<std::size_t>(c.study.trials) * c.study.alphas.size());
    const auto start = std::chrono::steady_clock::now();
    const StudyResult r = run_study(c.study, c.filter, c.simulation, filters,
                                    [&](int done, int) { bar.update(static_cast<std::size_t>(done)); });
    bar.finish();
    write_table(a.out, r, c);
    j["study_wall_s"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    for (const StudyCell& cell : r.cells) {
      j["study"].push_back({{"filter", filter_name(cell.filter)},
                            {"alpha", c.study.alphas[cell.level]},
                            {"beta", c.study.betas[cell.level]},
                            {"successes", cell.successes},
                            {"trials", cell.trials},
                            {"mean_trial_wall_s", cell.wall_s / cell.trials},
                            {"mean_trial_simulated_s", cell.simulated_s / cell.trials},
                            {"failed_trials_and_steps", cell.failures}});
    }
  }
  write_run_json(a.out, j, c.study.threads, dump_hybrid_config(c));
  spdlog::info("wrote {}", a.out);
  return 0;
}

}  // namespace

Run add_hybrid_sim_command(CLI::App& app) {
  auto args = std::make_shared<HybridSimArgs>();
  app.add_option("--config", args->config, "YAML options (see config/hybrid/default.yaml)");
  app.add_option("--out", args->out, "output folder")->capture_default_str();
  app.add_option("--trials", args->trials, "trials per filter and clutter level (default 100)");
  app.add_option("--threads", args->threads, "worker threads, 0 = all cores");
  app.add_option("--particles", args->particles, "FastSLAM particles (default 500)");
  app.add_option("--trial", args->trial,
                 "re-run one trial of the first clutter level alone with a per-step trace (trialN_FILTER.csv)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--filters", args->filters, "filters to run (FASTSLAM,EKF,HYBRID)")->delimiter(',');
  app.add_flag("--no-study", args->no_study, "only the figures and the speed run");
  app.add_flag("--no-figures", args->no_figures, "only Table 1");
  return [args] { return run_hybrid_sim(*args); };
}

}  // namespace lookahead::app
