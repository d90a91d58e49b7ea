// SPDX-License-Identifier: MIT
// The Slurm job scripts of a study: an sbatch array of N tasks, task I running
// `lookahead study run STUDY --shard I/N`, and a merge job that runs `lookahead study merge`
// after every task ended (afterany: the merge reports what is missing when a task failed or
// was cancelled, so that a resubmission can complete it). Paths in the scripts are absolute:
// the binary, the study file and the working directory must be the same on every node (a
// shared file system), since the tasks run where Slurm puts them.
#pragma once

#include <cstddef>
#include <string>

namespace lookahead::exploration {

struct SlurmJobOptions {
  std::string binary;            ///< absolute path of lookahead
  std::string study;             ///< absolute path of the study file
  std::string workdir;           ///< absolute; relative paths in the study start here
  std::string out;               ///< the study's output folder (absolute)
  std::string name;              ///< job name
  std::size_t shards = 1;        ///< array tasks (N)
  std::size_t max_parallel = 0;  ///< array throttle (%K); 0 = no limit
  int cpus_per_task = 1;         ///< also the workers each task runs
  std::string partition;         ///< empty: the cluster's default
  std::string time;              ///< per-task limit in a form sbatch takes ("2:00:00"); empty: default
};

/// The array job script (logs in OUT/slurm/logs/array_%A_%a.log).
std::string slurm_array_script(const SlurmJobOptions& o);
/// The merge job script (log in OUT/slurm/logs/merge_%j.log).
std::string slurm_merge_script(const SlurmJobOptions& o);
/// A shell script submitting both, the merge after the array: what --submit does.
std::string slurm_submit_script(const SlurmJobOptions& o);

/// Single-quoted for a POSIX shell.
std::string shell_quote(const std::string& text);

}  // namespace lookahead::exploration
