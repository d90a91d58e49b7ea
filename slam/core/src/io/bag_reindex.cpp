// SPDX-License-Identifier: MIT
#include "bag_reindex.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <vector>

#include "lookahead/slam/io/parse_error.hpp"

namespace lookahead::slam {
namespace {

namespace fs = std::filesystem;

constexpr std::uintmax_t kRoomMargin = 16u << 20;  // the index and the tool's own files

// The copy is as large as the bag: a temporary folder without room for it is refused before
// the tool starts, not when the disk fills under it.
void check_room(const std::string& path) {
  std::error_code ec;
  const fs::path tmp = fs::temp_directory_path(ec);
  const std::uintmax_t need = fs::file_size(path, ec);
  if (ec) return;  // the open that follows names what is wrong with the file
  const fs::space_info room = fs::space(tmp, ec);
  if (ec || room.available >= need + kRoomMargin) return;
  throw ParseError(
      path, 0, "index", "",
      fmt::format("the bag has no index (recording interrupted or file truncated); reading it needs a "
                  "copy `rosbag reindex` rebuilds, {:.1f} MB, and the temporary folder {} has {:.1f} MB "
                  "free: point TMPDIR at a folder with room",
                  static_cast<double>(need) / 1e6, tmp.string(), static_cast<double>(room.available) / 1e6));
}

fs::path fresh_folder() {
  static std::atomic<int> counter{0};
  const fs::path dir =
      fs::temp_directory_path() / ("lookahead-reindex-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// Runs argv with stdout and stderr into `output`; the exit status, or -1 when it could not
// start. posix_spawnp, not a shell: file names reach the tool as they are.
int run(const std::vector<std::string>& argv, const fs::path& output) {
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  posix_spawn_file_actions_t io;
  posix_spawn_file_actions_init(&io);
  posix_spawn_file_actions_addopen(&io, STDOUT_FILENO, output.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&io, STDOUT_FILENO, STDERR_FILENO);
  pid_t pid = 0;
  const int started = ::posix_spawnp(&pid, args[0], &io, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&io);
  if (started != 0) return -1;
  int status = 0;
  if (::waitpid(pid, &status, 0) != pid) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// The tool's last non-empty line: its reason, without the progress bar before it.
std::string last_line(const fs::path& file) {
  std::ifstream in(file);
  std::string line, last;
  while (std::getline(in, line, '\n')) {
    const auto cr = line.find_last_of('\r');
    if (cr != std::string::npos) line = line.substr(cr + 1);
    if (line.find_first_not_of(" \t") != std::string::npos) last = line;
  }
  return last;
}

}  // namespace

ReindexedBag::ReindexedBag(const std::string& path) {
  check_room(path);
  const fs::path dir = fresh_folder();
  folder_ = dir.string();
  const fs::path output = dir / "reindex.out";
  const int status = run({"rosbag", "reindex", "--output-dir", folder_, path}, output);
  const fs::path copy = dir / fs::path(path).filename();
  if (status == 0 && fs::is_regular_file(copy)) {
    copy_ = copy.string();
    return;
  }
  const std::string why = status == 127 || status < 0
                              ? "`rosbag reindex` is not available (Debian package python3-rosbag)"
                              : "`rosbag reindex` could not rebuild it: " + last_line(output);
  fs::remove_all(dir);
  throw ParseError(path, 0, "index", "", "the bag has no index (recording interrupted or file truncated); " + why);
}

ReindexedBag::~ReindexedBag() {
  std::error_code ec;
  fs::remove_all(folder_, ec);
}

}  // namespace lookahead::slam
