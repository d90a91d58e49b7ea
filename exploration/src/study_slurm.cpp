// SPDX-License-Identifier: MIT
#include "lookahead/exploration/study_slurm.hpp"

#include <fmt/format.h>

namespace lookahead::exploration {
namespace {

std::string header(const SlurmJobOptions& o, const std::string& name, const std::string& log, int cpus) {
  std::string s = "#!/bin/bash\n";
  s += "#SBATCH --job-name=" + name + "\n";
  s += "#SBATCH --output=" + o.out + "/slurm/logs/" + log + "\n";
  s += "#SBATCH --chdir=" + o.workdir + "\n";
  s += fmt::format("#SBATCH --cpus-per-task={}\n#SBATCH --ntasks=1\n", cpus);
  if (!o.partition.empty()) s += "#SBATCH --partition=" + o.partition + "\n";
  if (!o.time.empty()) s += "#SBATCH --time=" + o.time + "\n";
  return s;
}

}  // namespace

std::string shell_quote(const std::string& text) {
  std::string q = "'";
  for (const char c : text) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

std::string slurm_array_script(const SlurmJobOptions& o) {
  std::string s = header(o, o.name, "array_%A_%a.log", o.cpus_per_task);
  s += fmt::format("#SBATCH --array=0-{}{}\n", o.shards - 1, o.max_parallel ? fmt::format("%{}", o.max_parallel) : "");
  s += "# One shard of the study per array task; finished missions are skipped, so the same\n"
       "# array can be submitted again to complete what a failed or cancelled task left.\n"
       "set -euo pipefail\n";
  // The shard count is written here, not read from SLURM_ARRAY_TASK_COUNT, so that a
  // resubmission of only some tasks (--array=3,7) still splits the plan the same way.
  s += fmt::format("exec {} study run {} --shard \"${{SLURM_ARRAY_TASK_ID}}/{}\" --jobs {}\n", shell_quote(o.binary),
                   shell_quote(o.study), o.shards, o.cpus_per_task);
  return s;
}

std::string slurm_merge_script(const SlurmJobOptions& o) {
  std::string s = header(o, o.name + "-merge", "merge_%j.log", 1);
  s += "# Runs after every array task ended (submitted with --dependency=afterany:ARRAY), so\n"
       "# the staging folders of missions killed with their task can go.\n"
       "set -euo pipefail\n";
  s += fmt::format("find {} -maxdepth 1 -name '*.partial' -exec rm -rf {{}} +\n", shell_quote(o.out + "/runs"));
  s += fmt::format("exec {} study merge {}\n", shell_quote(o.binary), shell_quote(o.study));
  return s;
}

std::string slurm_submit_script(const SlurmJobOptions& o) {
  const std::string dir = o.out + "/slurm";
  return fmt::format(
      "#!/bin/bash\n# Submits the study's array and its merge job; prints both job ids.\n"
      "set -euo pipefail\n"
      "array=$(sbatch --parsable {0})\narray=${{array%%;*}}\n"
      "merge=$(sbatch --parsable --dependency=afterany:\"$array\" {1})\nmerge=${{merge%%;*}}\n"
      "echo \"array job $array, merge job $merge\"\n",
      shell_quote(dir + "/array.sbatch"), shell_quote(dir + "/merge.sbatch"));
}

}  // namespace lookahead::exploration
