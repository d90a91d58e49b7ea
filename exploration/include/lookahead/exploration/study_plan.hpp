// SPDX-License-Identifier: MIT
// A study's plan: every mission with a stable id made from what determines its result, the
// world file's bytes (or the generated world's name and seed), the world's resolution,
// pixel rule and start, the strategy, the seed and every effective mission option. Equal ids
// mean equal runs wherever and in whichever shard they execute; a changed input changes the
// id of exactly the missions it affects. The plan is written as OUT/plan.csv, a table with
// one row per mission (index, id, world, strategy, seed, folder), which `study run` checks
// before it runs anything, so that a study file edited after `study plan` runs nothing
// stale.
#pragma once

#include <string>
#include <vector>

#include "lookahead/exploration/study.hpp"

namespace lookahead::exploration {

struct PlannedMission {
  StudyRun run;
  std::string id;      ///< 16 hex digits (FNV-1a 64 of the inputs)
  std::string folder;  ///< run_id(): the folder under OUT/runs/
};

/// FNV-1a 64 (Fowler, Noll, Vo) of `bytes`, continuing from `state`.
std::uint64_t fnv1a64(const std::string& bytes, std::uint64_t state = 0xcbf29ce484222325ULL);

/// Hashes of what each world is: the file's bytes, or the generator's name and seed. Throws
/// slam::ParseError (study file, line, worlds.name, path) when a world file cannot be read.
std::vector<std::string> world_fingerprints(const StudySpec& spec);

/// plan_runs() with ids and folders; `fingerprints` from world_fingerprints(spec).
std::vector<PlannedMission> plan_missions(const StudySpec& spec, const std::vector<std::string>& fingerprints);
std::vector<PlannedMission> plan_missions(const StudySpec& spec);

/// The plan.csv text of `plan`.
std::string plan_csv(const StudySpec& spec, const std::vector<PlannedMission>& plan);
/// OUT/plan.csv
std::string plan_path(const StudySpec& spec);
/// Writes plan.csv atomically (through a temporary file and a rename).
void write_plan(const StudySpec& spec, const std::vector<PlannedMission>& plan);
/// Throws slam::ParseError naming plan.csv, the first row that differs and both ids when the
/// written plan is not `plan`: the study file or a world changed since it was written.
void check_plan(const StudySpec& spec, const std::vector<PlannedMission>& plan);

}  // namespace lookahead::exploration
