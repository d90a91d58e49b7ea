// SPDX-License-Identifier: MIT
// The verbs of `lookahead study`: plan, run (one shard or all), merge, slurm, and the plain
// `lookahead study STUDY.yaml` that plans, runs every mission locally and merges.
#pragma once

#include <cstddef>
#include <string>

namespace lookahead::app {

struct StudyArgs {
  std::string verb;  // "" (all locally), plan, run, merge, slurm
  std::string file;
  std::string out;    // overrides the study's out
  unsigned jobs = 0;  // 0 = every core
  std::string shard;  // run: "I/N"; empty: SLURM_ARRAY_TASK_ID/COUNT, or every mission
  // slurm
  std::size_t shards = 0;  // 0 = one per mission, at most 1000
  std::string partition, time;
  int cpus_per_task = 1;
  std::size_t max_parallel = 0;
  bool submit = false;
};

int study_plan(const StudyArgs& a);
int study_run(const StudyArgs& a);
int study_merge(const StudyArgs& a);
int study_local(const StudyArgs& a);
int study_slurm(const StudyArgs& a);

}  // namespace lookahead::app
