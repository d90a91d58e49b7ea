// SPDX-License-Identifier: MIT
// Provenance as a run.json block (header-only: the libraries that write run.json already
// use nlohmann-json).
#pragma once

#include <nlohmann/json.hpp>

#include "lookahead/slam/io/provenance.hpp"

namespace lookahead::slam {

inline nlohmann::json to_json(const Provenance& p) {
  return {{"commit", p.commit}, {"version", p.version}, {"date_utc", p.date_utc},
          {"cpu", p.cpu},       {"cores", p.cores},     {"threads", p.threads}};
}

}  // namespace lookahead::slam
