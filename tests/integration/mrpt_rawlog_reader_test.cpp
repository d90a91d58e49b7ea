// SPDX-License-Identifier: MIT
// read_mrpt_rawlog() against the one-loop dataset Debian ships with mrpt-common, plus the
// failure modes: a missing file and random bytes are ParseErrors; a truncated copy keeps the
// scans before the break.
#include <gtest/gtest.h>
#include <mrpt/io/CFileOutputStream.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/serialization/CArchive.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

#include "lookahead/slam/io/laser_log.hpp"
#include "lookahead/slam/io/parse_error.hpp"

namespace lookahead::slam {
namespace {

const std::string kOneLoop = "/usr/share/mrpt/datasets/2006-01ENE-21-SENA_Telecom Faculty_one_loop_only.rawlog";

/// A file in the temp directory that is removed when the test ends.
class TempFile {
 public:
  explicit TempFile(const std::string& name) : path_(std::filesystem::temp_directory_path() / name) {}
  ~TempFile() {
    std::error_code ec;
    std::filesystem::remove(path_, ec);
  }
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;

  void write(const std::vector<char>& bytes) const {
    std::ofstream out(path_, std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  }
  [[nodiscard]] std::string path() const { return path_.string(); }

 private:
  std::filesystem::path path_;
};

std::vector<char> read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

#define SKIP_WITHOUT_DATASET() \
  if (!std::filesystem::exists(kOneLoop)) GTEST_SKIP() << "mrpt-common not installed: " << kOneLoop

TEST(MrptRawlogReader, ReadsOneLoopDataset) {
  SKIP_WITHOUT_DATASET();
  const LaserLog log = read_mrpt_rawlog(kOneLoop);

  // Action/sensory-frame layout: 225 frames of one scan each and 224 odometry actions. The
  // file opens with a frame, so the first scan (record 1) has no action before it.
  EXPECT_EQ(log.lines_read, 449u);
  EXPECT_EQ(log.bad_lines, 0u);
  ASSERT_EQ(log.scans.size(), 225u);
  EXPECT_EQ(log.scans.front().source_line, 1u);
  EXPECT_EQ(log.scans.back().source_line, 449u);

  for (const LaserScan& scan : log.scans) {
    // A SICK-style 180 degree scanner at 0.5 degree steps, mounted 0.78 m ahead of the axle.
    ASSERT_EQ(scan.ranges.size(), 361u);
    EXPECT_NEAR(scan.angle_min, -M_PI / 2.0, 1e-6);
    EXPECT_NEAR(scan.angle_increment, M_PI / 360.0, 1e-7);
    EXPECT_NEAR(scan.bearing(360), M_PI / 2.0, 1e-5);
    EXPECT_DOUBLE_EQ(scan.max_range, 80.0);
    EXPECT_NEAR(scan.laser_offset.x, 0.78, 1e-6);
    EXPECT_NEAR(scan.laser_offset.y, 0.0, 1e-9);
    EXPECT_NEAR(scan.laser_offset.theta, 0.0, 1e-9);
  }

  // Real stamps from 2006-01-21 09:03:45 UTC, a 59 s drive, scans every 0.2 .. 0.65 s.
  EXPECT_NEAR(log.scans.front().timestamp, 1137834225.713386, 1e-5);
  EXPECT_NEAR(log.scans.back().timestamp, 1137834284.788331, 1e-5);
  double path_length = 0.0;
  std::size_t no_returns = 0;
  for (std::size_t i = 1; i < log.scans.size(); ++i) {
    const double dt = log.scans[i].timestamp - log.scans[i - 1].timestamp;
    EXPECT_GT(dt, 0.19) << "scan " << i;
    EXPECT_LT(dt, 0.7) << "scan " << i;
    const double step = log.scans[i - 1].odometry.between(log.scans[i].odometry).norm();
    EXPECT_LT(step, 1.0) << "scan " << i;  // a wheelchair-speed robot, not a jump
    path_length += step;
  }
  for (const LaserScan& scan : log.scans) {
    for (std::size_t b = 0; b < scan.ranges.size(); ++b) no_returns += scan.is_return(b) ? 0 : 1;
  }

  // Odometry starts at the origin and integrates to a 76 m drive that ends 21.7 m away.
  const Pose2& first = log.scans.front().odometry;
  EXPECT_DOUBLE_EQ(first.x, 0.0);
  EXPECT_DOUBLE_EQ(first.y, 0.0);
  EXPECT_DOUBLE_EQ(first.theta, 0.0);
  const Pose2& last = log.scans.back().odometry;
  EXPECT_NEAR(last.x, -4.8024, 1e-3);
  EXPECT_NEAR(last.y, -21.1637, 1e-3);
  EXPECT_NEAR(last.theta, -1.8623, 1e-3);
  EXPECT_NEAR(path_length, 76.35, 0.1);
  // Invalid readings became no-returns: 9312 of the 81225 beams.
  EXPECT_EQ(no_returns, 9312u);
}

TEST(MrptRawlogReader, MissingFileThrowsParseError) {
  const std::string missing = (std::filesystem::temp_directory_path() / "lookahead_no_such_file.rawlog").string();
  try {
    (void)read_mrpt_rawlog(missing);
    FAIL() << "expected ParseError";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.file(), missing);
    EXPECT_NE(std::string(e.what()).find(missing), std::string::npos);
  }
}

TEST(MrptRawlogReader, GarbageFileThrowsParseError) {
  TempFile file("lookahead_garbage_test.rawlog");
  std::mt19937 rng(20060121u);  // fixed seed: the same bytes on every run
  std::uniform_int_distribution<int> byte(0, 255);
  std::vector<char> bytes(4096);
  for (char& b : bytes) b = static_cast<char>(byte(rng));
  file.write(bytes);

  try {
    (void)read_mrpt_rawlog(file.path());
    FAIL() << "expected ParseError";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.file(), file.path());
    EXPECT_EQ(e.line(), 1u);  // the very first record is already unreadable
  }

  // Skipping cannot resynchronise a binary stream: the read stops with nothing kept.
  LogReadOptions options;
  options.skip_bad_lines = true;
  const LaserLog log = read_mrpt_rawlog(file.path(), options);
  EXPECT_TRUE(log.scans.empty());
  EXPECT_EQ(log.bad_lines, 1u);
  EXPECT_FALSE(log.first_bad_line_message.empty());
}

TEST(MrptRawlogReader, TruncatedFileKeepsScansReadBeforeTheBreak) {
  SKIP_WITHOUT_DATASET();
  std::vector<char> bytes = read_bytes(kOneLoop);
  ASSERT_GT(bytes.size(), 100000u);
  bytes.resize(100000);  // cut the gzip stream mid-record
  TempFile file("lookahead_truncated_test.rawlog");
  file.write(bytes);

  // The scans before the break are mapped; where it stopped is said, not thrown.
  const LaserLog log = read_mrpt_rawlog(file.path());
  EXPECT_EQ(log.bad_lines, 0u);
  EXPECT_NE(log.stopped_early.find("cannot deserialise"), std::string::npos) << log.stopped_early;
  EXPECT_GT(log.scans.size(), 50u);
  EXPECT_LT(log.scans.size(), 225u);
  EXPECT_GT(log.lines_read, log.scans.back().source_line);  // the broken record came later
}

// The bytes of a plain rawlog (written at `path`) of one valid 361-beam scan.
std::vector<char> valid_scan_rawlog(const std::string& path) {
  {
    mrpt::io::CFileOutputStream out(path);
    auto archive = mrpt::serialization::archiveFrom(out);
    mrpt::obs::CObservation2DRangeScan scan;
    scan.aperture = 3.14159f;
    scan.resizeScan(361);
    for (std::size_t i = 0; i < 361; ++i) scan.setScanRange(i, 1.5f), scan.setScanRangeValidity(i, true);
    archive << scan;
  }
  return read_bytes(path);
}

// A rawlog of one 361-beam scan whose beam count is rewritten to claim 2^31 - 16 beams:
// MRPT's deserialiser believes it and allocates gigabytes.
std::vector<char> scan_claiming_too_many_beams(const std::string& path) {
  std::vector<char> bytes = valid_scan_rawlog(path);
  const std::uint32_t beams = 361, claimed = 0x7ffffff0;
  const auto at = std::search(bytes.begin(), bytes.end(), reinterpret_cast<const char*>(&beams),
                              reinterpret_cast<const char*>(&beams) + sizeof beams);
  EXPECT_NE(at, bytes.end());
  if (at != bytes.end()) std::memcpy(&*at, &claimed, sizeof claimed);
  return bytes;
}

// The reader runs in a process that serves one read after another: a file it cannot parse,
// and one that takes the reader process down (MRPT crashes on the claimed 2^31 beams, or
// runs into the memory limit), each end in a ParseError naming the file, and the reads after
// them still work (a new reader process takes over).
TEST(MrptRawlogReader, ReadsGoOnAfterFilesTheReaderCannotTake) {
  SKIP_WITHOUT_DATASET();
  TempFile huge("lookahead_huge_claim_test.rawlog");
  huge.write(scan_claiming_too_many_beams(huge.path()));
  TempFile garbage("lookahead_garbage_then_good_test.rawlog");
  garbage.write(std::vector<char>(512, 'x'));
  for (const std::string& bad : {garbage.path(), huge.path(), garbage.path()}) {
    try {
      (void)read_mrpt_rawlog(bad);
      ADD_FAILURE() << "expected ParseError for " << bad;
    } catch (const ParseError& e) {
      EXPECT_EQ(e.file(), bad);
      if (bad == huge.path()) EXPECT_NE(std::string(e.what()).find("the reader"), std::string::npos) << e.what();
    }
    EXPECT_EQ(read_mrpt_rawlog(kOneLoop).scans.size(), 225u) << "after " << bad;
  }
}

// A caller that forks after its first read: both copies go on reading at the same time, each
// through a reader of its own (sharing the parent's would interleave their messages).
TEST(MrptRawlogReader, AForkedCallerReadsThroughItsOwnReader) {
  SKIP_WITHOUT_DATASET();
  ASSERT_EQ(read_mrpt_rawlog(kOneLoop).scans.size(), 225u);
  const auto read_many = [] {
    int good = 0;
    for (int k = 0; k < 10; ++k) {
      try {
        good += read_mrpt_rawlog(kOneLoop).scans.size() == 225u;
      } catch (const std::exception&) {
      }
    }
    return good;
  };
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) std::_Exit(read_many() == 10 ? 0 : 1);
  EXPECT_EQ(read_many(), 10);
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "the forked copy's reads failed";
}

// A scan whose direction flag holds the byte 2 (the rawlog fuzzer's UBSan finding): MRPT
// copies the byte into a bool unchecked; the reader names the field instead of reading an
// invalid bool. The flag is the byte after the class name, the version byte and the aperture.
TEST(MrptRawlogReader, AScanDirectionOtherThanZeroOrOneIsABadRecord) {
  TempFile file("lookahead_scan_direction_test.rawlog");
  std::vector<char> bytes = valid_scan_rawlog(file.path());
  const std::string name = "CObservation2DRangeScan";
  const auto at = std::search(bytes.begin(), bytes.end(), name.begin(), name.end());
  ASSERT_NE(at, bytes.end());
  const auto flag = static_cast<std::size_t>(at - bytes.begin()) + name.size() + 1 + sizeof(float);
  ASSERT_LT(flag, bytes.size());
  ASSERT_EQ(bytes[flag], 1);  // MRPT's default: right to left
  bytes[flag] = 2;
  file.write(bytes);
  try {
    (void)read_mrpt_rawlog(file.path());
    FAIL() << "expected ParseError";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.field(), "rightToLeft") << e.what();
    EXPECT_EQ(e.value(), "2") << e.what();
  }
}

}  // namespace
}  // namespace lookahead::slam
