// SPDX-License-Identifier: MIT
// read_mrpt_rawlog(): the MRPT reader in a child process with limits (rawlog_guard.hpp).
// The child writes one message to the pipe: 'L' and the log, or 'E' and a ParseError.
#include "rawlog_guard.hpp"

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <new>
#include <string>
#include <system_error>
#include <type_traits>

#include "lookahead/slam/io/parse_error.hpp"
#include "lookahead/slam/limits/input_limits.hpp"

namespace lookahead::slam {
namespace {

class Writer {
 public:
  template <class T>
  void put(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    const auto* p = reinterpret_cast<const char*>(&v);
    bytes_.append(p, sizeof(T));
  }
  void put(const std::string& s) {
    put(static_cast<std::uint64_t>(s.size()));
    bytes_ += s;
  }
  void put(const Pose2& p) { put(p.x), put(p.y), put(p.theta); }
  void put(const LogEvent& e) { put(static_cast<std::uint64_t>(e.count)), put(e.first); }
  [[nodiscard]] const std::string& bytes() const { return bytes_; }

 private:
  std::string bytes_;
};

class Reader {
 public:
  Reader(const std::string& bytes, const std::string& path) : bytes_(bytes), path_(path) {}
  template <class T>
  void get(T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    need(sizeof(T));
    std::memcpy(&v, bytes_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
  }
  void get(std::string& s) {
    std::uint64_t n = 0;
    get(n);
    need(n);
    s.assign(bytes_, pos_, n);
    pos_ += n;
  }
  void get(Pose2& p) { get(p.x), get(p.y), get(p.theta); }
  void get(LogEvent& e) {
    std::uint64_t n = 0;
    get(n), get(e.first);
    e.count = n;
  }
  void need(std::uint64_t n) const {
    if (n > bytes_.size() - pos_) throw ParseError(path_, 0, "", "", "rawlog reader: incomplete answer");
  }

 private:
  const std::string& bytes_;
  const std::string& path_;
  std::size_t pos_ = 0;
};

void put_log(Writer& w, const LaserLog& log) {
  w.put('L');
  w.put(static_cast<std::uint64_t>(log.lines_read)), w.put(static_cast<std::uint64_t>(log.bad_lines));
  w.put(log.first_bad_line_message), w.put(log.stopped_early);
  w.put(log.non_finite), w.put(log.time_reversals), w.put(log.odometry_jumps);
  w.put(static_cast<std::uint64_t>(log.scans.size()));
  for (const LaserScan& s : log.scans) {
    w.put(s.timestamp), w.put(s.logger_timestamp), w.put(s.angle_min), w.put(s.angle_increment);
    w.put(s.max_range), w.put(s.laser_offset), w.put(s.odometry);
    w.put(static_cast<std::uint64_t>(s.source_line));
    w.put(static_cast<std::uint64_t>(s.ranges.size()));
    for (const float r : s.ranges) w.put(r);
  }
}

void get_log(Reader& r, LaserLog& log) {
  std::uint64_t lines = 0, bad = 0, scans = 0;
  r.get(lines), r.get(bad), r.get(log.first_bad_line_message), r.get(log.stopped_early);
  r.get(log.non_finite), r.get(log.time_reversals), r.get(log.odometry_jumps);
  r.get(scans);
  log.lines_read = lines, log.bad_lines = bad;
  for (std::uint64_t k = 0; k < scans; ++k) {
    LaserScan s;
    std::uint64_t line = 0, n = 0;
    r.get(s.timestamp), r.get(s.logger_timestamp), r.get(s.angle_min), r.get(s.angle_increment);
    r.get(s.max_range), r.get(s.laser_offset), r.get(s.odometry), r.get(line), r.get(n);
    r.need(n * sizeof(float));
    s.source_line = line;
    s.ranges.resize(n);
    for (float& v : s.ranges) r.get(v);
    log.scans.push_back(std::move(s));
  }
}

void put_error(Writer& w, const ParseError& e) {
  w.put('E');
  w.put(static_cast<std::uint64_t>(e.line())), w.put(e.field()), w.put(e.value()), w.put(e.reason());
}

void write_all(int fd, const std::string& bytes) {
  for (std::size_t done = 0; done < bytes.size();) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;
    done += static_cast<std::size_t>(n);
  }
}

std::string read_all(int fd) {
  std::string out;
  char buffer[1 << 16];
  for (;;) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return out;
    out.append(buffer, static_cast<std::size_t>(n));
  }
}

bool under_address_sanitizer() {
#if defined(__SANITIZE_ADDRESS__)
  return true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
  return true;
#endif
#endif
  return false;
}

[[noreturn]] void run_child(int fd, const std::string& path, const LogReadOptions& options,
                            const detail::RawlogLimits& limits) {
  // ASan reserves terabytes of address space for its shadow: an RLIMIT_AS would stop it
  // before the reader starts; the sanitizer's own allocator limit stands in under ASan.
  if (!under_address_sanitizer()) {
    const rlimit memory{limits.memory_bytes, limits.memory_bytes};
    setrlimit(RLIMIT_AS, &memory);
  }
  const rlimit cpu{limits.cpu_seconds, limits.cpu_seconds + 5};
  setrlimit(RLIMIT_CPU, &cpu);
  Writer w;
  try {
    put_log(w, detail::read_mrpt_rawlog_unguarded(path, options));
  } catch (const ParseError& e) {
    w = Writer{};
    put_error(w, e);
  } catch (const std::bad_alloc&) {
    w = Writer{};
    put_error(w, ParseError(path, 0, "", "",
                            "the file claims more memory than the reader's limit of " +
                                std::to_string(limits.memory_bytes >> 20) + " MB (corrupt?)"));
  } catch (const std::exception& e) {
    w = Writer{};
    put_error(w, ParseError(path, 0, "", "", std::string("cannot read: ") + e.what()));
  }
  write_all(fd, w.bytes());
  ::close(fd);
  std::_Exit(0);  // no destructors or atexit handlers of the parent's objects
}

LaserLog decode(const std::string& bytes, const std::string& path) {
  Reader r(bytes, path);
  char tag = 0;
  r.get(tag);
  if (tag == 'E') {
    std::uint64_t line = 0;
    std::string field, value, reason;
    r.get(line), r.get(field), r.get(value), r.get(reason);
    throw ParseError(path, line, field, value, reason);
  }
  if (tag != 'L') throw ParseError(path, 0, "", "", "rawlog reader: malformed answer");
  LaserLog log;
  log.path = path;
  get_log(r, log);
  return log;
}

std::string describe_exit(int status, const detail::RawlogLimits& limits) {
  if (WIFSIGNALED(status) && WTERMSIG(status) == SIGXCPU) {
    return "reading took over " + std::to_string(limits.cpu_seconds) + " s of CPU time (corrupt file?)";
  }
  if (WIFSIGNALED(status)) return "the reader crashed (signal " + std::to_string(WTERMSIG(status)) + "; corrupt file?)";
  return "the reader stopped without an answer (exit " + std::to_string(WEXITSTATUS(status)) + ")";
}

}  // namespace

detail::RawlogLimits detail::rawlog_limits(std::uint64_t file_bytes) {
  RawlogLimits l;
  l.memory_bytes = std::max<std::uint64_t>(std::uint64_t{1} << 30, 64 * file_bytes);
  l.memory_bytes = std::min(l.memory_bytes, limits::available_memory_bytes());
  l.cpu_seconds = std::max<std::uint64_t>(60, 10 * (file_bytes >> 20));
  return l;
}

LaserLog read_mrpt_rawlog(const std::string& path, const LogReadOptions& options) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    throw ParseError(path, 0, "", "", "no such file (or not a regular file)");
  }
  const detail::RawlogLimits limits = detail::rawlog_limits(std::filesystem::file_size(path, ec));
  int fds[2];
  if (::pipe(fds) != 0) throw std::system_error(errno, std::generic_category(), "pipe");
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]), ::close(fds[1]);
    throw std::system_error(errno, std::generic_category(), "fork");
  }
  if (pid == 0) {
    ::close(fds[0]);
    run_child(fds[1], path, options, limits);
  }
  ::close(fds[1]);
  const std::string answer = read_all(fds[0]);
  ::close(fds[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (answer.empty()) throw ParseError(path, 0, "", "", describe_exit(status, limits));
  return decode(answer, path);
}

}  // namespace lookahead::slam
