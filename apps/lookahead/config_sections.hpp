// SPDX-License-Identifier: MIT
// Every configuration section lookahead reads, in one table: its name (also its folder under
// config/), what it configures, its documented defaults and its loader.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace lookahead::app {

struct ConfigSection {
  std::string name;                               ///< slam | segslam | hybrid | slam3d | mission | study
  std::string purpose;                            ///< one line: which command reads it and how
  std::function<std::string()> dump;              ///< the defaults as YAML with comments
  std::function<void(const std::string&)> check;  ///< loads a file; throws on the first error
};

const std::vector<ConfigSection>& config_sections();

/// docs/config.md: every section's keys with default, unit and meaning, from the dumps.
std::string config_reference();

}  // namespace lookahead::app
