// SPDX-License-Identifier: MIT
// `lookahead config`: the one front door to every configuration section. `dump` prints a
// section's documented defaults (the source of config/<section>/default.yaml), `check`
// loads a file through the section's own loader (a map_server world in config/worlds/
// through the world loader), `reference` prints docs/config.md.
#include <fmt/format.h>

#include <filesystem>
#include <stdexcept>

#include "commands.hpp"
#include "config_sections.hpp"
#include "lookahead/exploration/world_loader.hpp"
#include "lookahead/slam/io/parse_error.hpp"

namespace lookahead::app {
namespace {

struct ConfigArgs {
  std::string section = "slam";
  std::string file;
  std::string check_section;  // empty: from the file's folder under config/
};

const ConfigSection& section_named(const std::string& name) {
  for (const ConfigSection& s : config_sections()) {
    if (name == s.name) return s;
  }
  std::string names;
  for (const ConfigSection& s : config_sections()) names += (names.empty() ? "" : " | ") + s.name;
  throw std::invalid_argument(fmt::format("unknown config section '{}': expected {}", name, names));
}

// A map_server world description (image, resolution, origin...) is no configuration
// section: worlds are named by the mission and study files that use them.
constexpr const char* kWorldFolder = "worlds";

// config/<folder>/x.yaml names its section; robot presets are mission files.
std::string section_of_path(const std::string& path) {
  const std::string folder = std::filesystem::path(path).parent_path().filename().string();
  if (folder == "robot") return "mission";
  if (folder == kWorldFolder) return kWorldFolder;
  for (const ConfigSection& s : config_sections()) {
    if (folder == s.name) return folder;
  }
  throw std::invalid_argument(
      fmt::format("{}: cannot tell which section this file configures from its folder '{}': pass "
                  "--section (slam | segslam | hybrid | slam3d | mission | study | worlds)",
                  path, folder));
}

int check(const ConfigArgs& a) {
  const std::string name = a.check_section.empty() ? section_of_path(a.file) : a.check_section;
  if (name == kWorldFolder) {
    const exploration::World w = exploration::load_map_yaml(a.file);
    fmt::print("{}: ok (map_server world, {:.2f} m x {:.2f} m, {:.0f} m^2 free)\n", a.file, w.width_m(), w.height_m(),
               w.free_area_m2());
    return 0;
  }
  section_named(name).check(a.file);
  fmt::print("{}: ok ({} configuration)\n", a.file, name);
  return 0;
}

}  // namespace

Run add_config_command(CLI::App& app) {
  auto a = std::make_shared<ConfigArgs>();
  app.require_subcommand(1);
  CLI::App* dump = app.add_subcommand("dump", "print a section's documented defaults (YAML)");
  dump->add_option("section", a->section, "slam | segslam | hybrid | slam3d | mission | study")->capture_default_str();
  CLI::App* chk = app.add_subcommand("check", "load a YAML file and report the first error");
  chk->add_option("file", a->file, "the YAML file")->required();
  chk->add_option("--section", a->check_section,
                  "which section the file configures, or worlds for a map_server world (default: its folder "
                  "under config/)");
  CLI::App* ref = app.add_subcommand("reference", "every section as Markdown (docs/config.md)");
  return [a, dump, chk, ref] {
    if (dump->parsed()) {
      fmt::print("{}", section_named(a->section).dump());
    } else if (chk->parsed()) {
      return check(*a);
    } else if (ref->parsed()) {
      fmt::print("{}", config_reference());
    }
    return 0;
  };
}

}  // namespace lookahead::app
