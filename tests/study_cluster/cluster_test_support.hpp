// SPDX-License-Identifier: MIT
// Shared by the study cluster tests: running a shell command, a tiny study file, reading
// results.csv without its timing columns, and a one-node Slurm cluster started and stopped
// around each test by scripts/slurm_local.sh.
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace lookahead::test {

namespace fs = std::filesystem;

struct Shell {
  int code;
  std::string output;
};

inline std::string read_file(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// `cmd` through /bin/sh, standard output and error together.
inline Shell shell(const std::string& cmd) {
  static int counter = 0;
  const fs::path out = fs::temp_directory_path() /
                       ("lookahead-cluster-" + std::to_string(::getpid()) + "-" + std::to_string(counter++) + ".txt");
  const int status = std::system((cmd + " > " + out.string() + " 2>&1").c_str());
  Shell r{WIFEXITED(status) ? WEXITSTATUS(status) : 128, read_file(out)};
  fs::remove(out);
  return r;
}

/// A fresh folder under the temporary directory, removed by the destructor.
struct TempDir {
  fs::path path;
  explicit TempDir(const std::string& name)
      : path(fs::temp_directory_path() / (name + "-" + std::to_string(::getpid()))) {
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TempDir() { fs::remove_all(path); }
};

/// 2 generated worlds x 2 strategies x `seeds` seeds, true pose, `time_limit` simulated s.
inline std::string tiny_study(const std::string& name, const fs::path& out, int seeds, double time_limit) {
  std::ostringstream s;
  s << "name: " << name << "\nout: " << out.string()
    << "\nworlds:\n  - {name: maze}\n  - {name: corridor}\nstrategies: [nearest, utility]\n"
    << "seeds: {from: 1, count: " << seeds << "}\npose_source: truth\ntime_limit: " << time_limit << "\n";
  return s.str();
}

/// results.csv rows without the columns that measure the machine (wall time, speed-up).
inline std::vector<std::string> results_without_timing(const fs::path& csv) {
  std::ifstream in(csv);
  std::vector<std::string> rows;
  std::vector<bool> keep;
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> cells;
    std::stringstream row(line);
    for (std::string cell; std::getline(row, cell, ',');) cells.push_back(cell);
    if (line.back() == ',') cells.emplace_back();
    if (keep.empty()) {
      for (const std::string& c : cells) keep.push_back(c != "wall_time_s" && c != "real_time_factor");
    }
    std::string kept;
    for (std::size_t i = 0; i < cells.size() && i < keep.size(); ++i)
      if (keep[i]) kept += cells[i] + ",";
    rows.push_back(kept);
  }
  return rows;
}

/// Folders under OUT/runs that hold a finished run (run.json present, not a staging folder).
inline std::set<std::string> finished_runs(const fs::path& out) {
  std::set<std::string> names;
  if (!fs::exists(out / "runs")) return names;
  for (const auto& e : fs::directory_iterator(out / "runs")) {
    const std::string n = e.path().filename().string();
    if (n.find(".partial") == std::string::npos && fs::exists(e.path() / "run.json")) names.insert(n);
  }
  return names;
}

/// The one-node cluster of scripts/slurm_local.sh in its own folder, for one test.
class SlurmCluster : public ::testing::Test {
 protected:
  void SetUp() override {
    if (::geteuid() != 0) GTEST_SKIP() << "the one-node Slurm cluster needs root";
    if (shell("command -v slurmctld && command -v munged").code != 0)
      GTEST_SKIP() << "slurm-wlm and munge are not installed (scripts/install_deps.sh)";
    // A fixed folder: the ctest cleanup fixture stops this cluster even when a test died.
    dir_ = LOOKAHEAD_TEST_SLURM_DIR;
    script_ =
        "LOOKAHEAD_SLURM_DIR=" + dir_.string() + " " + std::string(LOOKAHEAD_SOURCE_DIR) + "/scripts/slurm_local.sh";
    const Shell r = shell(script_ + " start");
    started_ = true;
    ASSERT_EQ(r.code, 0) << r.output;
    ::setenv("SLURM_CONF", (dir_ / "slurm.conf").c_str(), 1);
  }
  void TearDown() override {
    if (!started_) return;
    const Shell r = shell(script_ + " stop");
    EXPECT_EQ(r.code, 0) << r.output;
    for (const char* pid : {"munged.pid", "slurmctld.pid", "slurmd.pid"})
      EXPECT_FALSE(fs::exists(dir_ / pid)) << pid << " left behind";
    fs::remove_all(dir_);
  }

  /// "COMPLETED", "CANCELLED", "RUNNING"... of a job (every task of an array ended when
  /// no task is pending or running).
  static std::string job_state(const std::string& id) {
    return shell("scontrol show job " + id + " | grep -o 'JobState=[A-Z_]*' | sort -u").output;
  }
  /// Waits until job `id` (all its array tasks) left the queue; false after `seconds`.
  static bool wait_for_job(const std::string& id, double seconds) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (std::chrono::steady_clock::now() < end) {
      if (shell("squeue -h -j " + id + " -o %i 2>/dev/null").output.empty()) return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(300));
    }
    return false;
  }

  fs::path dir_;
  std::string script_;
  bool started_ = false;
};

}  // namespace lookahead::test
