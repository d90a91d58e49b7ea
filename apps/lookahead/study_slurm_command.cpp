// SPDX-License-Identifier: MIT
// `lookahead study slurm STUDY.yaml`: the sbatch array and merge scripts in OUT/slurm, and
// with --submit both jobs submitted, the merge after the array (study_slurm.hpp).
#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "lookahead/exploration/study_plan.hpp"
#include "lookahead/exploration/study_slurm.hpp"
#include "lookahead/slam/io/parse_error.hpp"
#include "study_verbs.hpp"

namespace lookahead::app {
namespace {

namespace ex = exploration;
namespace fs = std::filesystem;

constexpr std::size_t kMaxArrayTasks = 1000;  // Slurm's default MaxArraySize is 1001

// The first `name` on PATH that can be executed, or "".
std::string find_on_path(const std::string& name) {
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "");
  for (std::string dir; std::getline(dirs, dir, ':');) {
    const fs::path candidate = fs::path(dir.empty() ? "." : dir) / name;
    if (::access(candidate.c_str(), X_OK) == 0) return candidate.string();
  }
  return "";
}

void write_script(const fs::path& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
  out.close();
  if (!out) throw slam::ParseError(path.string(), 0, "", "", "cannot write");
  fs::permissions(path, fs::perms::owner_exec | fs::perms::group_exec | fs::perms::others_exec, fs::perm_options::add);
}

// Runs `command` through the shell; its standard output, or throws with it on failure.
std::string run_command(const std::string& command) {
  FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
  if (!pipe) throw std::runtime_error("cannot run " + command);
  std::string output;
  std::array<char, 512> buffer{};
  while (std::fgets(buffer.data(), buffer.size(), pipe)) output += buffer.data();
  const int status = ::pclose(pipe);
  if (status != 0) throw std::runtime_error(command + " failed: " + output);
  return output;
}

ex::SlurmJobOptions job_options(const StudyArgs& a, const ex::StudySpec& spec, std::size_t missions) {
  ex::SlurmJobOptions o;
  o.binary = fs::read_symlink("/proc/self/exe").string();
  o.study = fs::absolute(a.file).lexically_normal().string();
  o.workdir = fs::current_path().string();
  o.out = fs::absolute(spec.out).lexically_normal().string();
  o.name = "lookahead-" + spec.name;
  o.shards = a.shards ? a.shards : std::min(missions, kMaxArrayTasks);
  if (o.shards > missions)
    throw slam::ParseError("command line", 0, "--shards", std::to_string(a.shards),
                           fmt::format("more shards than the study's {} missions", missions));
  o.max_parallel = a.max_parallel;
  o.cpus_per_task = a.cpus_per_task;
  o.partition = a.partition;
  o.time = a.time;
  return o;
}

}  // namespace

int study_slurm(const StudyArgs& a) {
  const ex::StudySpec spec = ex::load_study(a.file);
  if (!a.out.empty())
    throw slam::ParseError("command line", 0, "--out", a.out,
                           "set `out` in the study file: every array task reads it there");
  const std::vector<ex::PlannedMission> plan = ex::plan_missions(spec);
  ex::write_plan(spec, plan);
  const ex::SlurmJobOptions o = job_options(a, spec, plan.size());
  const fs::path dir = fs::path(o.out) / "slurm";
  fs::create_directories(dir / "logs");
  write_script(dir / "array.sbatch", ex::slurm_array_script(o));
  write_script(dir / "merge.sbatch", ex::slurm_merge_script(o));
  write_script(dir / "submit.sh", ex::slurm_submit_script(o));
  spdlog::info(
      "{} mission(s) in {} array task(s), {} core(s) each; scripts in {} (submit with "
      "{})",
      plan.size(), o.shards, o.cpus_per_task, dir.string(), (dir / "submit.sh").string());
  if (!a.submit) return 0;
  if (find_on_path("sbatch").empty())
    throw slam::ParseError("command line", 0, "--submit", "sbatch",
                           "sbatch is not on PATH: run this on a Slurm login node (Debian: "
                           "slurm-client), or scripts/slurm_local.sh start for a one-node "
                           "cluster; the scripts are written");
  const std::string printed = run_command("bash " + ex::shell_quote((dir / "submit.sh").string()));
  std::fputs(printed.c_str(), stdout);
  return 0;
}

}  // namespace lookahead::app
