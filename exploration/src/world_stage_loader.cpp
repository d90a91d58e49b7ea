// SPDX-License-Identifier: MIT
// Loader (c): a Player/Stage .world and the floorplan bitmap it names. Stage (libstage
// model.cc / stage.cc) centres a model on its `pose [x y z yaw(deg)]` and stretches the
// bitmap to its `size [sx sy sz]` metres; Stage 2 worlds give `bitmap_resolution` instead.
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <sstream>
#include <stdexcept>

#include "lookahead/exploration/world_loader.hpp"
#include "lookahead/slam/io/parse_error.hpp"
#include "lookahead/slam/limits/input_limits.hpp"
#include "world_image.hpp"
#include "world_stage_syntax.hpp"

namespace lookahead::exploration {
namespace {

namespace fs = std::filesystem;
using detail::StageFile;
using detail::StageModel;
using detail::StageProperty;
using slam::ParseError;

std::string joined(const StageProperty& p) {
  std::string s;
  for (const auto& v : p.values) s += (s.empty() ? "" : " ") + v;
  return s;
}

// Model types are floorplans when their define chain reaches Stage's `floorplan` (map.inc)
// or Stage 2's `map`.
bool is_floorplan(std::string type, const StageFile& f) {
  for (int depth = 0; depth < 32; ++depth) {
    if (type == "floorplan" || type == "map") return true;
    const auto it = f.defines.find(type);
    if (it == f.defines.end()) return false;
    type = it->second.parent;
  }
  return false;
}

// A property of the instance, else of its define chain (Stage's inheritance).
const StageProperty* property(const StageModel& m, const StageFile& f, const std::string& key) {
  if (auto it = m.properties.find(key); it != m.properties.end()) return &it->second;
  std::string type = m.type;
  for (int depth = 0; depth < 32; ++depth) {
    const auto d = f.defines.find(type);
    if (d == f.defines.end()) return nullptr;
    if (auto it = d->second.body.properties.find(key); it != d->second.body.properties.end()) {
      return &it->second;
    }
    type = d->second.parent;
  }
  return nullptr;
}

double number(const StageProperty& p, std::size_t i, const std::string& key, const std::string& file) {
  double v = 0.0;
  if (i >= p.values.size()) throw ParseError(file, p.line, key, joined(p), "too few values");
  const std::string& t = p.values[i];
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
  if (ec != std::errc() || end != t.data() + t.size() || !std::isfinite(v)) {
    throw ParseError(file, p.line, key, joined(p), "not a number");
  }
  return v;
}

// Stage resolves the bitmap against the world file's folder. The shared copies sit one
// folder up from worlds/ without their bitmaps/ or maps/ folder, so the file name is also
// tried there; world.source() records which file was used.
fs::path find_bitmap(const StageProperty& p, const std::string& file) {
  const fs::path dir = fs::path(file).parent_path();
  const fs::path name = p.values.at(0);
  for (const fs::path& c : {dir / name, dir / name.filename(), dir.parent_path() / name.filename()}) {
    if (fs::is_regular_file(c)) return c;
  }
  throw ParseError(file, p.line, "bitmap", p.values.at(0), "image not found");
}

const StageModel& the_floorplan(const StageFile& f, const std::string& file) {
  const StageModel* found = nullptr;
  for (const auto& m : f.models) {
    if (!is_floorplan(m.type, f) || !property(m, f, "bitmap")) continue;
    if (found) throw ParseError(file, m.line, m.type, "", "more than one floorplan with a bitmap");
    found = &m;
  }
  if (!found) throw ParseError(file, 0, "floorplan", "", "no floorplan/map model with a bitmap");
  return *found;
}

// Quarter turns of the model's yaw; other angles would need resampling walls diagonally.
int quarter_turns(const StageModel& m, const StageFile& f, const std::string& file, Eigen::Vector2d& centre) {
  const StageProperty* pose = property(m, f, "pose");
  if (!pose) return 0;
  centre = {number(*pose, 0, "pose", file), number(*pose, 1, "pose", file)};
  // Stage 4: [x y z yaw]; Stage 2 (test_2008_sal2.world): [x y yaw].
  const std::size_t yaw_index = pose->values.size() >= 4 ? 3 : 2;
  const double yaw = pose->values.size() > 2 ? number(*pose, yaw_index, "pose", file) : 0.0;
  const double q = yaw / 90.0;
  if (std::abs(q - std::round(q)) > 1e-6) {
    throw ParseError(file, pose->line, "pose", joined(*pose), "only multiples of 90 deg are supported");
  }
  return ((static_cast<int>(std::lround(q)) % 4) + 4) % 4;
}

}  // namespace

World load_stage_world(const std::string& path, const StageWorldOptions& options) {
  if (!(options.resolution >= 0)) {
    throw std::invalid_argument("StageWorldOptions.resolution must be >= 0, got " + std::to_string(options.resolution));
  }
  std::ifstream in(path);
  if (!in) throw ParseError(path, 0, "", "", "cannot open file");
  std::stringstream text;
  text << in.rdbuf();
  const StageFile f = detail::parse_stage_world(text.str(), path);
  const StageModel& m = the_floorplan(f, path);
  const StageProperty& bitmap = *property(m, f, "bitmap");
  const fs::path image = find_bitmap(bitmap, path);
  cv::Mat mask =
      detail::read_free_mask(image.string(), options.rule.value_or(PixelRule::stage()), path, bitmap.line, "bitmap");
  double sx = 0.0, sy = 0.0;
  if (const StageProperty* size = property(m, f, "size")) {
    sx = number(*size, 0, "size", path);
    sy = number(*size, 1, "size", path);
  } else if (const StageProperty* r = property(m, f, "bitmap_resolution")) {
    sx = number(*r, 0, "bitmap_resolution", path) * mask.cols;
    sy = number(*r, 0, "bitmap_resolution", path) * mask.rows;
  }
  if (!(sx > 0 && sy > 0)) throw ParseError(path, m.line, "size", "", "floorplan needs a positive size");
  const double rx = sx / mask.cols, ry = sy / mask.rows;
  const double res = options.resolution > 0 ? options.resolution : std::min(rx, ry);
  // Checked in floating point before any integer conversion or allocation.
  if (!(sx / res * (sy / res) <= static_cast<double>(slam::limits::kMaxImagePixels))) {
    throw ParseError(path, m.line, "size", std::to_string(sx) + " x " + std::to_string(sy),
                     "at " + std::to_string(res) + " m/pixel over 8192 x 8192 pixels (limits::kMaxImagePixels)");
  }
  const int w = std::max(1, static_cast<int>(std::lround(sx / res)));
  const int h = std::max(1, static_cast<int>(std::lround(sy / res)));
  // Nearest neighbour at the finer pixel size only repeats pixels, so no wall goes missing.
  if (w != mask.cols || h != mask.rows) cv::resize(cv::Mat(mask), mask, {w, h}, 0, 0, cv::INTER_NEAREST);
  Eigen::Vector2d centre{0.0, 0.0};
  const int turns = quarter_turns(m, f, path, centre);
  const cv::RotateFlags flags[] = {cv::ROTATE_90_COUNTERCLOCKWISE, cv::ROTATE_180, cv::ROTATE_90_CLOCKWISE};
  if (turns != 0) cv::rotate(cv::Mat(mask), mask, flags[turns - 1]);
  const Eigen::Vector2d half = 0.5 * res * Eigen::Vector2d(mask.cols, mask.rows);
  World world = detail::world_from_mask(mask, res, centre - half);
  world.set_source(path + " (bitmap " + image.string() + ")");
  return world;
}

}  // namespace lookahead::exploration
