// SPDX-License-Identifier: MIT
// Internal: the subset of Player/Stage's world-file syntax a floor plan needs. A file is a
// list of entries: `include "f"`, `key value`, `define NAME PARENT ( body )` and model
// instances `TYPE ( body )`; a value is a word, a "string" or a [ list ]; `#` starts a comment.
// Keys like `point[0]` keep their index (the Roomba block in roomba_lse_arena.world).
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace lookahead::exploration::detail {

struct StageProperty {
  std::vector<std::string> values;  ///< one for a word/string, several for a list
  std::size_t line = 0;
};

struct StageModel {
  std::string type;
  std::size_t line = 0;
  std::map<std::string, StageProperty> properties;
  std::vector<StageModel> children;
};

struct StageDefine {
  std::string parent;
  StageModel body;
};

struct StageFile {
  std::map<std::string, StageDefine> defines;
  std::vector<StageModel> models;  ///< top-level instances, in file order
};

/// Parses the text of a .world file; errors throw ParseError(file, line, ...).
StageFile parse_stage_world(const std::string& text, const std::string& file);

}  // namespace lookahead::exploration::detail
