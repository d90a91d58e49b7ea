// SPDX-License-Identifier: MIT
// `lookahead eval`: Kuemmerle relative error of a trajectory, and the entropy of a map.
#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "lookahead/slam/eval/absolute_error.hpp"
#include "lookahead/slam/eval/map_divergence.hpp"
#include "lookahead/slam/eval/map_entropy.hpp"
#include "lookahead/slam/eval/relative_error.hpp"
#include "lookahead/slam/io/laser_log.hpp"
#include "lookahead/slam/io/trajectory_io.hpp"
#include "lookahead/slam/io/tum_trajectory.hpp"

namespace lookahead::app {
namespace {

struct EvalArgs {
  std::string relations, reference_log, reference, trajectory, map, reference_map;
  double tolerance = 0.005;
  bool json = false;
};

// A reference trajectory from a corrected CARMEN log (e.g. GMapping's .gfs.log): its poses
// at its scans. Used where no benchmark relations exist (fr101, CSAIL).
std::vector<slam::StampedPose> reference_from_log(const std::string& path) {
  const slam::LaserLog log = slam::read_carmen_log(path);
  std::vector<slam::StampedPose> ref;
  for (const auto& s : log.scans) ref.push_back({s.timestamp, s.odometry});
  return ref;
}

// Which reference pose each estimate pose was paired with, in words and JSON.
void print_association(const std::vector<slam::StampedPose>& reference, std::size_t matched, double tolerance,
                       nlohmann::json& j) {
  fmt::print(
      "timestamps associated: each reference pose with the nearest estimate stamp within +-{:.4f} s, no "
      "clock offset; {} of {} reference poses matched\n",
      tolerance, matched, reference.size());
  j["association"] = {{"method", "nearest stamp"},
                      {"tolerance_s", tolerance},
                      {"offset_s", 0.0},
                      {"matched", matched},
                      {"reference_poses", reference.size()}};
}

std::vector<slam::StampedPose> read_reference(const EvalArgs& a) {
  return a.reference.empty() ? reference_from_log(a.reference_log) : slam::read_any_trajectory(a.reference);
}

int run_eval(const EvalArgs& a) {
  nlohmann::json j;
  if (!a.trajectory.empty()) {
    const auto trajectory = slam::read_any_trajectory(a.trajectory);
    std::vector<slam::Relation> relations;
    if (!a.relations.empty()) {
      relations = slam::read_relations(a.relations);
    } else if (!a.reference_log.empty() || !a.reference.empty()) {
      const auto reference = read_reference(a);
      relations = slam::relations_from_reference(reference);
      const slam::AbsoluteError ate = slam::absolute_trajectory_error(reference, trajectory, a.tolerance);
      print_association(reference, ate.matched, a.tolerance, j);
      fmt::print(
          "absolute error after SE(2) alignment: RMSE {:.3f} m, mean {:.3f} m, max {:.3f} m "
          "({} poses matched)\n",
          ate.rmse, ate.mean, ate.max, ate.matched);
      j["ate_rmse_m"] = ate.rmse;
      j["ate_mean_m"] = ate.mean;
      j["ate_max_m"] = ate.max;
      j["ate_matched"] = ate.matched;
    } else {
      throw std::runtime_error("eval: --trajectory needs --relations, --reference or --reference-log");
    }
    const slam::RelativeError e = slam::relative_error(relations, trajectory, a.tolerance);
    fmt::print(
        "relative error: translation {:.3f} +- {:.3f} m, rotation {:.2f} +- {:.2f} deg "
        "({} relations used, {} without a matching pose)\n",
        e.trans_mean, e.trans_std, e.rot_mean, e.rot_std, e.used, e.skipped);
    j["trans_mean_m"] = e.trans_mean;
    j["trans_std_m"] = e.trans_std;
    j["rot_mean_deg"] = e.rot_mean;
    j["rot_std_deg"] = e.rot_std;
    j["relations_used"] = e.used;
    j["relations_skipped"] = e.skipped;
  }
  if (!a.map.empty()) {
    const slam::MapEntropy h = slam::map_entropy(slam::read_map(a.map));
    fmt::print("map entropy: {:.1f} nats over {} observed cells ({:.4f} per cell)\n", h.total, h.observed,
               h.per_cell());
    j["map_entropy_nats"] = h.total;
    j["map_observed_cells"] = h.observed;
  }
  if (!a.reference_map.empty()) {
    if (a.map.empty()) throw std::runtime_error("eval: --reference-map needs --map");
    const slam::MapDivergence d = slam::map_divergence(slam::read_map(a.reference_map), slam::read_map(a.map));
    fmt::print("KL divergence from the reference map (eq. 24 of P-SLAM): {:.1f} nats over {} cells\n", d.total,
               d.compared);
    j["kl_divergence_nats"] = d.total;
    j["kl_compared_cells"] = d.compared;
  }
  if (a.json) fmt::print("{}\n", j.dump());
  return 0;
}

}  // namespace

Run add_eval_command(CLI::App& app) {
  auto args = std::make_shared<EvalArgs>();
  app.add_option("--relations", args->relations, "benchmark .relations file (Kuemmerle et al. 2009)");
  app.add_option("--reference-log", args->reference_log,
                 "corrected CARMEN log used as reference instead of relations (consecutive scans)");
  app.add_option("--reference", args->reference,
                 "reference trajectory, TUM (timestamp tx ty tz qx qy qz qw) or 'timestamp x y theta'");
  app.add_option("--trajectory", args->trajectory,
                 "trajectory.txt or trajectory.tum written by `lookahead slam` (or any TUM file)");
  app.add_option("--map", args->map, "map .yaml (map_server) whose entropy to compute");
  app.add_option("--reference-map", args->reference_map,
                 "map .yaml taken as truth P: prints the KL divergence D(P || --map)");
  app.add_option("--tolerance", args->tolerance, "max stamp difference when matching poses [s]")->capture_default_str();
  app.add_flag("--json", args->json, "also print the figures as one JSON line");
  return [args] { return run_eval(*args); };
}

}  // namespace lookahead::app
