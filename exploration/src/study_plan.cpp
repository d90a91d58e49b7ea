// SPDX-License-Identifier: MIT
#include "lookahead/exploration/study_plan.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "lookahead/exploration/mission_config.hpp"
#include "lookahead/slam/io/parse_error.hpp"

namespace lookahead::exploration {
namespace {

namespace fs = std::filesystem;

bool is_generated(const std::string& name) { return name == "office" || name == "maze" || name == "corridor"; }

std::string hex(std::uint64_t v) { return fmt::format("{:016x}", v); }

std::string read_lines_of(const std::string& path, std::vector<std::string>& lines) {
  std::ifstream in(path);
  if (!in) return "cannot open file";
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return "";
}

}  // namespace

std::uint64_t fnv1a64(const std::string& bytes, std::uint64_t state) {
  for (const char c : bytes) {
    state ^= static_cast<unsigned char>(c);
    state *= 0x100000001b3ULL;
  }
  return state;
}

std::vector<std::string> world_fingerprints(const StudySpec& spec) {
  std::vector<std::string> out;
  for (const StudyWorld& w : spec.worlds) {
    if (is_generated(w.spec.name)) {
      out.push_back(fmt::format("generated {} seed {}", w.spec.name, w.spec.seed));
      continue;
    }
    std::ifstream in(w.spec.name, std::ios::binary);
    if (!in)
      throw slam::ParseError(spec.source, w.line, "worlds.name", w.spec.name,
                             "cannot read the world file (on a cluster, every node must see it "
                             "at this path)");
    std::stringstream bytes;
    bytes << in.rdbuf();
    out.push_back("file " + hex(fnv1a64(bytes.str())));
  }
  return out;
}

std::vector<PlannedMission> plan_missions(const StudySpec& spec, const std::vector<std::string>& fingerprints) {
  std::vector<PlannedMission> plan;
  for (const StudyRun& run : plan_runs(spec)) {
    const WorldSpec& w = spec.worlds[run.world].spec;
    std::string inputs = fingerprints.at(run.world) + fmt::format("\nresolution {}\npixel rule {}\nseed {}\n",
                                                                  w.image_resolution, w.pixel_rule, w.seed);
    if (w.start) inputs += fmt::format("start {} {} {}\n", w.start->x, w.start->y, w.start->theta);
    inputs += dump_mission_options(run_options(spec, run));
    plan.push_back({run, hex(fnv1a64(inputs)), run_id(spec, run)});
  }
  return plan;
}

std::vector<PlannedMission> plan_missions(const StudySpec& spec) {
  return plan_missions(spec, world_fingerprints(spec));
}

std::string plan_csv(const StudySpec& spec, const std::vector<PlannedMission>& plan) {
  std::string csv = "index,mission_id,world,strategy,seed,folder\n";
  for (std::size_t i = 0; i < plan.size(); ++i) {
    const PlannedMission& m = plan[i];
    csv += fmt::format("{},{},{},{},{},{}\n", i, m.id, spec.worlds[m.run.world].label, m.run.strategy, m.run.seed,
                       m.folder);
  }
  return csv;
}

std::string plan_path(const StudySpec& spec) { return spec.out + "/plan.csv"; }

void write_plan(const StudySpec& spec, const std::vector<PlannedMission>& plan) {
  fs::create_directories(spec.out);
  // Unique per process: shards that start together may all write the (same) plan.
  const std::string tmp = plan_path(spec) + fmt::format(".{}.tmp", ::getpid());
  std::ofstream out(tmp);
  out << plan_csv(spec, plan);
  out.close();
  if (!out) throw slam::ParseError(tmp, 0, "", "", "cannot write");
  fs::rename(tmp, plan_path(spec));
}

void check_plan(const StudySpec& spec, const std::vector<PlannedMission>& plan) {
  std::vector<std::string> written;
  const std::string path = plan_path(spec);
  if (const std::string why = read_lines_of(path, written); !why.empty())
    throw slam::ParseError(path, 0, "", "", why + ": run `lookahead study plan " + spec.source + "` first");
  std::istringstream expected(plan_csv(spec, plan));
  std::size_t line = 0;
  for (std::string want; std::getline(expected, want); ++line) {
    const std::string got = line < written.size() ? written[line] : "(end of file)";
    if (got != want)
      throw slam::ParseError(path, line + 1, "mission_id", got,
                             fmt::format("the study now plans \"{}\": {} or a world changed since "
                                         "`lookahead study plan`; nothing was run. Plan again "
                                         "(finished runs with unchanged ids are kept)",
                                         want, spec.source));
  }
  if (written.size() > line)
    throw slam::ParseError(path, line + 1, "mission_id", written[line],
                           "the study now plans fewer missions; plan again");
}

}  // namespace lookahead::exploration
