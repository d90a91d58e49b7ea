// SPDX-License-Identifier: MIT
// Loaders (a) image and (b) map_server YAML; the Stage loader is in world_stage_loader.cpp.
#include "lookahead/exploration/world_loader.hpp"

#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <set>

#include "lookahead/slam/io/parse_error.hpp"
#include "world_image.hpp"

namespace lookahead::exploration {
namespace {

namespace fs = std::filesystem;
using slam::ParseError;

std::size_t line_of(const YAML::Node& n) { return static_cast<std::size_t>(n.Mark().line + 1); }

template <typename T>
T scalar(const YAML::Node& n, const std::string& key, const std::string& file) {
  try {
    return n.as<T>();
  } catch (const YAML::Exception&) {
    throw ParseError(file, line_of(n), key, YAML::Dump(n), "wrong type");
  }
}

// Defaults are map_server's (the values lse_arena.yaml and maze.yaml spell out).
struct MapYaml {
  std::string image;
  double resolution = 0.0;
  Eigen::Vector2d origin{0.0, 0.0};
  bool negate = false;
  double occupied_thresh = 0.65;
  double free_thresh = 0.196;
};

void check_keys(const YAML::Node& root, const std::string& file) {
  static const std::set<std::string> known = {"image", "resolution",      "origin",     "negate",
                                              "mode",  "occupied_thresh", "free_thresh"};
  for (const auto& kv : root) {
    const auto key = kv.first.as<std::string>();
    if (!known.count(key)) throw ParseError(file, line_of(kv.first), key, "", "unknown key");
  }
  for (const char* key : {"image", "resolution", "origin"}) {
    if (!root[key]) throw ParseError(file, line_of(root), key, "", "missing key");
  }
}

void read_origin(const YAML::Node& n, const std::string& file, MapYaml& m) {
  if (!n.IsSequence() || n.size() < 2 || n.size() > 3) {
    throw ParseError(file, line_of(n), "origin", YAML::Dump(n), "expected [x, y, yaw]");
  }
  m.origin = {scalar<double>(n[0], "origin", file), scalar<double>(n[1], "origin", file)};
  // A rotated map_server map has no cell layout we could honour, and "ignore the yaw" (what
  // much of ROS does) would silently move the walls.
  if (n.size() == 3 && scalar<double>(n[2], "origin", file) != 0.0) {
    throw ParseError(file, line_of(n), "origin", YAML::Dump(n), "a non-zero yaw is not supported");
  }
}

MapYaml parse_map_yaml(const YAML::Node& root, const std::string& file) {
  check_keys(root, file);
  MapYaml m;
  m.image = scalar<std::string>(root["image"], "image", file);
  m.resolution = scalar<double>(root["resolution"], "resolution", file);
  if (!(m.resolution > 0)) {
    throw ParseError(file, line_of(root["resolution"]), "resolution", YAML::Dump(root["resolution"]), "must be > 0");
  }
  read_origin(root["origin"], file, m);
  if (root["negate"]) m.negate = scalar<int>(root["negate"], "negate", file) != 0;
  if (root["occupied_thresh"]) m.occupied_thresh = scalar<double>(root["occupied_thresh"], "occupied_thresh", file);
  if (root["free_thresh"]) m.free_thresh = scalar<double>(root["free_thresh"], "free_thresh", file);
  if (!(m.free_thresh >= 0 && m.free_thresh < m.occupied_thresh && m.occupied_thresh <= 1)) {
    const auto& n = root["free_thresh"] ? root["free_thresh"] : root["occupied_thresh"];
    throw ParseError(file, n ? line_of(n) : line_of(root), "free_thresh", std::to_string(m.free_thresh),
                     "need 0 <= free_thresh < occupied_thresh <= 1");
  }
  // trinary and scale share the free set p < free_thresh; raw reads values as occupancy.
  if (root["mode"]) {
    const auto mode = scalar<std::string>(root["mode"], "mode", file);
    if (mode != "trinary" && mode != "scale") {
      throw ParseError(file, line_of(root["mode"]), "mode", mode, "expected trinary or scale");
    }
  }
  return m;
}

}  // namespace

World load_image_world(const std::string& path, const ImageWorldOptions& options) {
  if (!(options.resolution > 0)) {
    throw ParseError(path, 0, "resolution", std::to_string(options.resolution), "must be > 0");
  }
  const cv::Mat mask = detail::read_free_mask(path, options.rule, path, 0, "image");
  World world = detail::world_from_mask(mask, options.resolution, options.origin);
  world.set_source(path);
  return world;
}

World load_map_yaml(const std::string& path) {
  YAML::Node root;
  try {
    root = YAML::LoadFile(path);
  } catch (const YAML::BadFile&) {
    throw ParseError(path, 0, "", "", "cannot open file");
  } catch (const YAML::ParserException& e) {
    throw ParseError(path, static_cast<std::size_t>(e.mark.line + 1), "", "", e.msg);
  }
  if (!root.IsMap()) throw ParseError(path, 1, "", "", "expected a YAML map");
  const MapYaml m = parse_map_yaml(root, path);
  fs::path image = m.image;
  if (image.is_relative()) image = fs::path(path).parent_path() / image;
  const cv::Mat mask = detail::read_free_mask(image.string(), PixelRule::map_server(m.free_thresh, m.negate), path,
                                              line_of(root["image"]), "image");
  World world = detail::world_from_mask(mask, m.resolution, m.origin);
  world.set_source(path);
  return world;
}

}  // namespace lookahead::exploration
