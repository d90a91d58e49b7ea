// SPDX-License-Identifier: MIT
// `lookahead study [plan|run|merge|slurm] STUDY.yaml`: worlds x strategies x seeds of
// exploration missions, locally on all cores or as a Slurm job array, resumable, with
// results.csv, summary.md (means, Welch's and paired t-tests), plots and report.html.
#include <memory>

#include "commands.hpp"
#include "lookahead/slam/io/parse_error.hpp"
#include "study_verbs.hpp"

namespace lookahead::app {
namespace {

int dispatch(StudyArgs a, const std::vector<std::string>& words) {
  if (words.size() == 1) {
    a.file = words[0];
  } else if (words.size() == 2) {
    a.verb = words[0];
    a.file = words[1];
  } else {
    throw slam::ParseError("command line", 0, "study", "", "expected STUDY.yaml or plan|run|merge|slurm STUDY.yaml");
  }
  if (a.verb.empty()) return study_local(a);
  if (a.verb == "plan") return study_plan(a);
  if (a.verb == "run") return study_run(a);
  if (a.verb == "merge") return study_merge(a);
  if (a.verb == "slurm") return study_slurm(a);
  throw slam::ParseError("command line", 0, "study", a.verb, "unknown verb: expected plan, run, merge or slurm");
}

}  // namespace

Run add_study_command(CLI::App& app) {
  auto a = std::make_shared<StudyArgs>();
  auto words = std::make_shared<std::vector<std::string>>();
  app.add_option("study", *words,
                 "STUDY.yaml (plan, run every mission here, merge), or one of\n"
                 "  plan STUDY.yaml   write OUT/plan.csv: every mission and its id\n"
                 "  run STUDY.yaml    run a shard (--shard I/N, or the Slurm array task's)\n"
                 "  merge STUDY.yaml  results.csv, summary.md, plots, report.html of what is done\n"
                 "  slurm STUDY.yaml  write (and with --submit, submit) the sbatch array + merge")
      ->required()
      ->expected(1, 2);
  app.add_option("--out", a->out, "output folder (default: the study's out, or out/study/<name>)");
  app.add_option("--jobs", a->jobs, "runs in parallel (default: every core)");
  app.add_option("--shard", a->shard,
                 "run: shard I/N, 0 <= I < N (default: SLURM_ARRAY_TASK_ID/SLURM_ARRAY_TASK_COUNT "
                 "under a Slurm array, else every mission)");
  app.add_option("--shards", a->shards, "slurm: array tasks (default: one per mission, <= 1000)");
  app.add_option("--partition", a->partition, "slurm: partition (default: the cluster's)");
  app.add_option("--time", a->time, "slurm: time limit per array task, e.g. 2:00:00");
  app.add_option("--cpus-per-task", a->cpus_per_task, "slurm: cores (and workers) per task")
      ->check(CLI::PositiveNumber);
  app.add_option("--max-parallel", a->max_parallel, "slurm: array tasks running at once (%K)");
  app.add_flag("--submit", a->submit, "slurm: submit the array and the merge job, print the ids");
  return [a, words] { return dispatch(*a, *words); };
}

}  // namespace lookahead::app
