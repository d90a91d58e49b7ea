// SPDX-License-Identifier: MIT
// read_mrpt_rawlog(): the MRPT reader in a child process with limits (rawlog_guard.hpp).
// For each request the child answers with one message: 'L' and the log, or 'E' and a
// ParseError.
#include "rawlog_guard.hpp"

#include <malloc.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <mutex>
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

// One request to the reader process: the file, the options the reader uses and its limits.
struct Request {
  std::string path;
  LogReadOptions options;
  detail::RawlogLimits limits;
};

std::string encode(const Request& q) {
  Writer w;
  w.put(q.path), w.put(q.options.skip_bad_lines), w.put(q.options.no_return_range);
  w.put(q.options.max_odometry_step), w.put(q.limits.memory_bytes), w.put(q.limits.cpu_seconds);
  return w.bytes();
}

Request decode_request(const std::string& bytes) {
  Request q;
  Reader r(bytes, q.path);
  r.get(q.path), r.get(q.options.skip_bad_lines), r.get(q.options.no_return_range);
  r.get(q.options.max_odometry_step), r.get(q.limits.memory_bytes), r.get(q.limits.cpu_seconds);
  return q;
}

// Messages on the socket: a 64-bit length, then the bytes. send() with MSG_NOSIGNAL, so a
// reader that died makes the write fail instead of raising SIGPIPE in the caller.
bool send_message(int fd, const std::string& bytes) {
  Writer w;
  w.put(bytes);
  const std::string& out = w.bytes();
  for (std::size_t done = 0; done < out.size();) {
    const ssize_t n = ::send(fd, out.data() + done, out.size() - done, MSG_NOSIGNAL);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<std::size_t>(n);
  }
  return true;
}

bool read_exactly(int fd, char* out, std::size_t size) {
  for (std::size_t done = 0; done < size;) {
    const ssize_t n = ::read(fd, out + done, size - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<std::size_t>(n);
  }
  return true;
}

// False when the other side closed or died before a whole message came.
bool receive_message(int fd, std::string& bytes) {
  std::uint64_t size = 0;
  if (!read_exactly(fd, reinterpret_cast<char*>(&size), sizeof size)) return false;
  if (size > (std::uint64_t{1} << 40)) return false;
  bytes.resize(size);
  return read_exactly(fd, bytes.data(), size);
}

// This process's address space [bytes] (/proc/self/statm: size in pages).
rlim_t mapped_bytes() {
  std::FILE* f = std::fopen("/proc/self/statm", "r");
  unsigned long pages = 0;
  if (f != nullptr) {
    if (std::fscanf(f, "%lu", &pages) != 1) pages = 0;
    std::fclose(f);
  }
  return static_cast<rlim_t>(pages) * static_cast<rlim_t>(::sysconf(_SC_PAGESIZE));
}

// Reads one file under the request's limits. The CPU limit counts from what this process has
// used so far, as it serves one request after another. True when the process may serve the
// next request: after an exception other than a ParseError or bad_alloc it starts afresh.
bool serve(int fd, const Request& q) {
  // The memory limit is room on top of what this process already maps (the caller's
  // libraries, copied by fork), so a small file gets little room and a size it falsely
  // claims fails at once instead of after MRPT has filled the memory it got.
  // ASan reserves terabytes of address space for its shadow: an RLIMIT_AS would stop it
  // before the reader starts; the sanitizer's own allocator limit stands in under ASan.
  if (!under_address_sanitizer()) {
    const rlimit memory{mapped_bytes() + q.limits.memory_bytes, RLIM_INFINITY};
    setrlimit(RLIMIT_AS, &memory);
  }
  rusage used{};
  getrusage(RUSAGE_SELF, &used);
  const auto spent = static_cast<rlim_t>(used.ru_utime.tv_sec + used.ru_stime.tv_sec);
  const rlimit cpu{spent + q.limits.cpu_seconds, RLIM_INFINITY};
  setrlimit(RLIMIT_CPU, &cpu);
  Writer w;
  bool healthy = true;
  try {
    put_log(w, detail::read_mrpt_rawlog_unguarded(q.path, q.options));
  } catch (const ParseError& e) {
    w = Writer{};
    put_error(w, e);
  } catch (const std::bad_alloc&) {  // unwound like any exception: the process serves on
    w = Writer{};
    put_error(w, ParseError(q.path, 0, "", "",
                            "the file claims more memory than the reader's limit of " +
                                std::to_string(q.limits.memory_bytes >> 20) + " MB (corrupt?)"));
  } catch (const std::exception& e) {
    w = Writer{};
    put_error(w, ParseError(q.path, 0, "", "", std::string("cannot read: ") + e.what()));
    healthy = false;
  }
  // The first byte says whether this process serves on ('K') or exits after this answer ('X').
  const bool sent = send_message(fd, (healthy ? "K" : "X") + w.bytes());
  malloc_trim(0);  // an idle reader gives the log's memory back
  return sent && healthy;
}

[[noreturn]] void run_reader_process(int fd) {
  // A crash in MRPT's deserialiser ends this process plainly: no handler the caller installed
  // (a sanitizer's, a fuzzer's) reports it as the caller's, and no core file is written. The
  // caller sees the signal and names the file.
  for (const int signal : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) std::signal(signal, SIG_DFL);
  const rlimit no_core{0, 0};
  setrlimit(RLIMIT_CORE, &no_core);
  std::string bytes;
  while (receive_message(fd, bytes)) {
    if (!serve(fd, decode_request(bytes))) break;
  }
  ::close(fd);
  std::_Exit(0);  // no destructors or atexit handlers of the parent's objects
}

// The reader process: forked at the first read and kept for the next ones, so a caller
// reading many files (the fuzzer, a study of rawlogs) forks once, not per file. A reader
// that crashed, ran over its CPU time or failed unexpectedly is replaced at the next read; so
// is one inherited by a forked copy of the caller, which must not share the parent's socket.
class ReaderProcess {
 public:
  ~ReaderProcess() {
    if (owner_ == ::getpid()) stop();
  }

  // The answer to `q`, or the reason the reader died before giving one.
  std::string read(const Request& q, std::string& death) {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (pid_ >= 0 && owner_ != ::getpid()) {  // the parent's reader: leave it to the parent
      ::close(fd_);
      pid_ = -1, fd_ = -1;
    }
    if (pid_ < 0) start();
    std::string answer;
    if (send_message(fd_, encode(q)) && receive_message(fd_, answer) && !answer.empty()) {
      if (answer.front() == 'X') stop();
      return answer.substr(1);
    }
    death = describe_exit(stop(), q.limits);
    return {};
  }

 private:
  void start() {
    int fds[2];
    if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, fds) != 0) {
      throw std::system_error(errno, std::generic_category(), "socketpair");
    }
    const pid_t pid = ::fork();
    if (pid < 0) {
      ::close(fds[0]), ::close(fds[1]);
      throw std::system_error(errno, std::generic_category(), "fork");
    }
    if (pid == 0) {
      ::close(fds[0]);
      run_reader_process(fds[1]);
    }
    ::close(fds[1]);
    pid_ = pid;
    fd_ = fds[0];
    owner_ = ::getpid();
  }

  // Closes the socket (a live reader then exits) and returns the reader's exit status.
  int stop() {
    if (pid_ < 0) return 0;
    ::close(fd_);
    int status = 0;
    while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
    }
    pid_ = -1, fd_ = -1;
    return status;
  }

  std::mutex mutex_;
  pid_t pid_ = -1;    // the reader
  int fd_ = -1;       // its socket
  pid_t owner_ = -1;  // the process that forked it
};

}  // namespace

detail::RawlogLimits detail::rawlog_limits(std::uint64_t file_bytes) {
  RawlogLimits l;
  l.memory_bytes = std::max<std::uint64_t>(std::uint64_t{64} << 20, 64 * file_bytes);
  l.memory_bytes = std::min(l.memory_bytes, limits::available_memory_bytes());
  l.cpu_seconds = std::max<std::uint64_t>(60, 10 * (file_bytes >> 20));
  return l;
}

LaserLog read_mrpt_rawlog(const std::string& path, const LogReadOptions& options) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    throw ParseError(path, 0, "", "", "no such file (or not a regular file)");
  }
  static ReaderProcess reader;
  const Request request{path, options, detail::rawlog_limits(std::filesystem::file_size(path, ec))};
  std::string death;
  const std::string answer = reader.read(request, death);
  if (answer.empty()) throw ParseError(path, 0, "", "", death);
  return decode(answer, path);
}

}  // namespace lookahead::slam
