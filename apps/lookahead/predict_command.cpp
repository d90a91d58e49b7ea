// SPDX-License-Identifier: MIT
// `lookahead predict MAP --target X,Y`: one P-SLAM prediction on a saved map, with the
// picture of the target region, the reference region, the control points and the
// hypothesis, and prediction.json with the figures.
#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>

#include "commands.hpp"
#include "lookahead/pipeline/pslam_config.hpp"
#include "lookahead/predictor/prediction_picture.hpp"
#include "lookahead/predictor/structure_predictor.hpp"
#include "lookahead/slam/io/map_io.hpp"
#include "lookahead/slam/io/parse_error.hpp"

namespace lookahead::app {
namespace {

struct PredictArgs {
  std::string map, out = "out/predict", config;
  std::vector<double> target;
  // Given on the command line: they override the config file's predictor section.
  std::optional<double> diameter, threshold, control_range;
};

predictor::PredictorOptions options_of(const PredictArgs& a) {
  predictor::PredictorOptions o = pipeline::load_pslam_options(a.config).prediction.predictor;
  if (a.diameter) o.surroundings_diameter = *a.diameter;
  if (a.threshold) o.similarity_threshold = *a.threshold;
  if (a.control_range) o.control_point_range = *a.control_range;
  predictor::validate(o);
  return o;
}

// A map_server map: its YAML, or the image beside a YAML of the same name.
slam::ProbabilityMap load_map(const std::string& path) {
  std::filesystem::path p(path);
  if (p.extension() != ".yaml" && p.extension() != ".yml") {
    const std::filesystem::path yaml = std::filesystem::path(p).replace_extension(".yaml");
    if (!std::filesystem::exists(yaml)) {
      throw slam::ParseError(path, 0, "", "", "needs the map_server YAML beside it: " + yaml.string());
    }
    p = yaml;
  }
  return slam::read_map(p.string());
}

nlohmann::json to_json(const predictor::Prediction& p) {
  nlohmann::json j{{"status", predictor::to_string(p.status)},
                   {"target", {p.target_x, p.target_y}},
                   {"transforms_scored", p.candidates},
                   {"predicted_area_m2", p.predicted_area},
                   {"seconds", p.seconds},
                   {"diameter_m", p.diameter},
                   {"corners", p.features.corners.size()},
                   {"lines", p.features.lines.size()}};
  if (p.alignment) {
    const auto& a = *p.alignment;
    j["psi"] = a.score.psi;
    j["control_point"] = {a.control.x, a.control.y};
    j["reference_point"] = {a.reference.x, a.reference.y};
    j["reference_to_target"] = {a.reference_to_target.x, a.reference_to_target.y, a.reference_to_target.theta};
  }
  return j;
}

int run_predict(const PredictArgs& a) {
  const slam::OccupancyGrid map = slam::to_occupancy_grid(load_map(a.map));
  const predictor::PredictorOptions options = options_of(a);
  const predictor::Prediction p = predictor::predict_structure(map, a.target[0], a.target[1], options);
  std::filesystem::create_directories(a.out);
  predictor::write_prediction_picture(a.out + "/prediction.png", map, p, options);
  if (p.hypothesis) slam::write_map(slam::to_probability_map(p.hypothesis->grid, 0), a.out, "hypothesis");
  std::ofstream(a.out + "/prediction.json") << to_json(p).dump(2) << "\n";
  fmt::print("{}: {}", a.map, predictor::to_string(p.status));
  if (p.alignment) fmt::print(", best Psi {:.3f} ({} transforms scored)", p.alignment->score.psi, p.candidates);
  if (p.hypothesis) fmt::print(", hypothesis {:.1f} m^2", p.predicted_area);
  fmt::print(" in {:.0f} ms; picture {}/prediction.png\n", 1000 * p.seconds, a.out);
  return p.status == predictor::Prediction::Status::kPredicted ? 0 : 3;
}

}  // namespace

Run add_predict_command(CLI::App& app) {
  auto a = std::make_shared<PredictArgs>();
  app.add_option("map", a->map, "map_server map: MAP.yaml, or MAP.pgm with MAP.yaml beside it")->required();
  app.add_option("--target", a->target, "the frontier cell f to predict around, X,Y [m]")
      ->required()
      ->expected(2)
      ->delimiter(',');
  app.add_option("--out", a->out, "output directory");
  app.add_option("--config", a->config, "YAML with a predictor: section (config/slam/default.yaml format)");
  app.add_option("--diameter", a->diameter, "d: surroundings and prediction range [m]");
  app.add_option("--threshold", a->threshold, "Psi threshold of a hypothesis (0.4..0.7)");
  app.add_option("--control-range", a->control_range, "control point within this of the target [m]");
  app.footer("Exit code 0 when a hypothesis was made, 3 when none cleared the threshold.");
  return [a] { return run_predict(*a); };
}

}  // namespace lookahead::app
