// SPDX-License-Identifier: MIT
// One share of a study's missions: shard I of N takes every mission whose plan index i has
// i mod N == I, so the worlds and strategies spread evenly over the shards and a mission's
// shard never changes what it computes (its seed comes from the study, not from its place).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace lookahead::exploration {

struct Shard {
  std::size_t index = 0;  ///< I, in [0, count)
  std::size_t count = 1;  ///< N >= 1
};

/// "I/N" with 0 <= I < N; throws std::invalid_argument naming the text and what is wrong.
Shard parse_shard(const std::string& text);

/// The shard of a Slurm array task: SLURM_ARRAY_TASK_ID of SLURM_ARRAY_TASK_COUNT (both
/// set by sbatch --array=0-(N-1)); nullopt outside an array. Throws std::invalid_argument
/// when the variables are set but make no shard.
std::optional<Shard> shard_from_slurm_environment();

/// The plan indices (0 .. missions - 1) in `shard`, increasing.
std::vector<std::size_t> shard_missions(std::size_t missions, const Shard& shard);

}  // namespace lookahead::exploration
