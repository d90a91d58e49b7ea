// SPDX-License-Identifier: MIT
#include "lookahead/slam/io/map_io.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>

#include "lookahead/slam/io/image_header.hpp"
#include "lookahead/slam/io/parse_error.hpp"

namespace lookahead::slam {
namespace {

constexpr double kOccupiedThresh = 0.65;
constexpr double kFreeThresh = 0.196;
constexpr int kUnknownGrey = 205;

template <typename T>
T yaml_value(const YAML::Node& root, const char* key, const std::string& file) {
  const YAML::Node n = root[key];
  if (!n) throw ParseError(file, 0, key, "", "missing key");
  try {
    return n.as<T>();
  } catch (const YAML::Exception&) {
    throw ParseError(file, static_cast<std::size_t>(n.Mark().line + 1), key, YAML::Dump(n), "bad value");
  }
}

}  // namespace

ProbabilityMap to_probability_map(const OccupancyGrid& grid, int margin_cells) {
  ProbabilityMap m;
  m.resolution = grid.resolution();
  CellIndex lo, hi;
  if (!grid.known_bounds(lo, hi)) return m;
  lo = {lo.x - margin_cells, lo.y - margin_cells};
  hi = {hi.x + margin_cells, hi.y + margin_cells};
  m.width = hi.x - lo.x + 1;
  m.height = hi.y - lo.y + 1;
  m.origin_x = lo.x * m.resolution;
  m.origin_y = lo.y * m.resolution;
  m.p.resize(static_cast<std::size_t>(m.width) * static_cast<std::size_t>(m.height));
  for (int y = 0; y < m.height; ++y) {
    for (int x = 0; x < m.width; ++x) {
      const CellIndex c{lo.x + x, lo.y + y};
      m.p[static_cast<std::size_t>(y * m.width + x)] = grid.is_known(c) ? grid.probability(c) : -1.0;
    }
  }
  return m;
}

void write_map(const ProbabilityMap& map, const std::string& dir, const std::string& name) {
  std::filesystem::create_directories(dir);
  cv::Mat image(map.height, map.width, CV_8UC1);
  for (int y = 0; y < map.height; ++y) {
    for (int x = 0; x < map.width; ++x) {
      const double p = map.at(x, y);
      // Grey = 255 (1 - p), so map_server's trinary thresholds classify every cell as it
      // would, and the probabilities survive for entropy; 205 is reserved for unknown.
      // The file's top row is the map's highest y.
      int grey = p < 0 ? kUnknownGrey : static_cast<int>(std::lround(255.0 * (1.0 - p)));
      if (p >= 0 && grey == kUnknownGrey) grey = kUnknownGrey - 1;
      image.at<std::uint8_t>(map.height - 1 - y, x) = static_cast<std::uint8_t>(grey);
    }
  }
  const std::string pgm = dir + "/" + name + ".pgm";
  if (!cv::imwrite(pgm, image)) throw ParseError(pgm, 0, "", "", "cannot write image");
  std::ofstream yaml(dir + "/" + name + ".yaml");
  yaml << "image: " << name << ".pgm\n"
       << "resolution: " << map.resolution << "\n"
       << "origin: [" << map.origin_x << ", " << map.origin_y << ", 0.0]\n"
       << "mode: trinary\nnegate: 0\noccupied_thresh: " << kOccupiedThresh << "\nfree_thresh: " << kFreeThresh << "\n";
  if (!yaml) throw ParseError(dir + "/" + name + ".yaml", 0, "", "", "cannot write file");
}

ProbabilityMap read_map(const std::string& yaml_path) {
  YAML::Node root;
  try {
    root = YAML::LoadFile(yaml_path);
  } catch (const YAML::BadFile&) {
    throw ParseError(yaml_path, 0, "", "", "cannot open file");
  } catch (const YAML::ParserException& e) {
    throw ParseError(yaml_path, static_cast<std::size_t>(e.mark.line + 1), "", "", e.msg);
  }
  ProbabilityMap m;
  const auto image_name = yaml_value<std::string>(root, "image", yaml_path);
  m.resolution = yaml_value<double>(root, "resolution", yaml_path);
  if (!(m.resolution > 0)) throw ParseError(yaml_path, 0, "resolution", std::to_string(m.resolution), "must be > 0");
  const auto origin = yaml_value<std::vector<double>>(root, "origin", yaml_path);
  if (origin.size() < 2) throw ParseError(yaml_path, 0, "origin", "", "needs [x, y, yaw]");
  m.origin_x = origin[0];
  m.origin_y = origin[1];
  const int negate = root["negate"] ? yaml_value<int>(root, "negate", yaml_path) : 0;
  std::filesystem::path image_path(image_name);
  if (image_path.is_relative()) image_path = std::filesystem::path(yaml_path).parent_path() / image_path;
  check_image_header(image_path.string(), yaml_path, 0, "image");
  cv::Mat image;
  try {
    image = cv::imread(image_path.string(), cv::IMREAD_GRAYSCALE);
  } catch (const cv::Exception& e) {  // a header OpenCV's decoder refuses
    throw ParseError(yaml_path, 0, "image", image_path.string(), "cannot read image: " + e.msg);
  }
  if (image.empty()) throw ParseError(yaml_path, 0, "image", image_path.string(), "cannot read image");
  check_image_size(image.cols, image.rows, yaml_path, 0, "image");
  m.width = image.cols;
  m.height = image.rows;
  m.p.resize(static_cast<std::size_t>(m.width) * static_cast<std::size_t>(m.height));
  for (int y = 0; y < m.height; ++y) {
    for (int x = 0; x < m.width; ++x) {
      const double v = image.at<std::uint8_t>(m.height - 1 - y, x) / 255.0;
      const double p = negate ? v : 1.0 - v;  // map_server: dark = occupied
      m.p[static_cast<std::size_t>(y * m.width + x)] =
          image.at<std::uint8_t>(m.height - 1 - y, x) == kUnknownGrey ? -1.0 : p;
    }
  }
  return m;
}

OccupancyGrid to_occupancy_grid(const ProbabilityMap& map, GridOptions options) {
  options.resolution = map.resolution;
  OccupancyGrid grid(options);
  for (int y = 0; y < map.height; ++y) {
    for (int x = 0; x < map.width; ++x) {
      const double p = map.at(x, y);
      if (p < 0) continue;
      const double q = std::clamp(p, 0.01, 0.99);
      const CellIndex c =
          grid.cell_at(map.origin_x + (x + 0.5) * map.resolution, map.origin_y + (y + 0.5) * map.resolution);
      grid.add_log_odds(c, static_cast<int>(std::lround(1000.0 * std::log(q / (1.0 - q)))));
    }
  }
  return grid;
}

}  // namespace lookahead::slam
