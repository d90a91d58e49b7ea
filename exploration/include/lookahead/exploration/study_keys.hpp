// SPDX-License-Identifier: MIT
// The keys of a study file, each with an example value and its meaning: the one list the
// study loader accepts and `lookahead config dump study` documents.
#pragma once

#include <set>
#include <string>
#include <vector>

namespace lookahead::exploration {

struct StudyKey {
  const char* key;
  const char* example;  ///< YAML text of an example value
  const char* doc;
};

/// Top-level keys of a study file.
const std::vector<StudyKey>& study_keys();
/// Keys of one entry of `worlds:`.
const std::vector<StudyKey>& study_world_keys();
/// The names of a key list (what the loader accepts).
std::set<std::string> key_names(const std::vector<StudyKey>& keys);
/// A documented, loadable study file listing every key (config dump study).
std::string dump_study_keys();

}  // namespace lookahead::exploration
