// SPDX-License-Identifier: MIT
#include "lookahead/exploration/study_shard.hpp"

#include <cstdlib>
#include <stdexcept>

namespace lookahead::exploration {
namespace {

// A whole decimal number without sign, spaces or trailing text.
std::optional<std::size_t> parse_count(const std::string& s) {
  if (s.empty() || s.size() > 18) return std::nullopt;
  std::size_t v = 0;
  for (const char c : s) {
    if (c < '0' || c > '9') return std::nullopt;
    v = v * 10 + static_cast<std::size_t>(c - '0');
  }
  return v;
}

}  // namespace

Shard parse_shard(const std::string& text) {
  const std::size_t slash = text.find('/');
  const auto bad = [&](const std::string& why) { return std::invalid_argument("shard \"" + text + "\": " + why); };
  if (slash == std::string::npos) throw bad("expected I/N, e.g. 0/4");
  const auto i = parse_count(text.substr(0, slash));
  const auto n = parse_count(text.substr(slash + 1));
  if (!i || !n) throw bad("expected I/N with whole numbers I >= 0 and N >= 1, e.g. 0/4");
  if (*n == 0) throw bad("N must be >= 1");
  if (*i >= *n) throw bad("I must be < N (shards are numbered 0 .. N-1)");
  return {*i, *n};
}

std::optional<Shard> shard_from_slurm_environment() {
  const char* id = std::getenv("SLURM_ARRAY_TASK_ID");
  const char* count = std::getenv("SLURM_ARRAY_TASK_COUNT");
  if (!id && !count) return std::nullopt;
  if (!id || !count)
    throw std::invalid_argument("SLURM_ARRAY_TASK_ID and SLURM_ARRAY_TASK_COUNT must both be set for an array task");
  try {
    return parse_shard(std::string(id) + "/" + count);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("from SLURM_ARRAY_TASK_ID/SLURM_ARRAY_TASK_COUNT: ") + e.what());
  }
}

std::vector<std::size_t> shard_missions(std::size_t missions, const Shard& shard) {
  std::vector<std::size_t> out;
  for (std::size_t i = shard.index; i < missions; i += shard.count) out.push_back(i);
  return out;
}

}  // namespace lookahead::exploration
