// SPDX-License-Identifier: MIT
// Reads an MRPT .rawlog through MRPT's own deserialisation, in either of its two layouts:
// action/sensory-frame pairs (odometry as increments) or a flat stream of observations
// (odometry as absolute CObservationOdometry readings).
#include <mrpt/core/Clock.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CRawlog.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPosePDF.h>
#include <mrpt/serialization/CArchive.h>

#include <cmath>
#include <cstddef>
#include <cstring>
#include <exception>
#include <filesystem>
#include <limits>
#include <memory>
#include <string>
#include <system_error>

#include "lookahead/slam/io/laser_log.hpp"
#include "lookahead/slam/io/odometry_check.hpp"
#include "lookahead/slam/io/parse_error.hpp"
#include "rawlog_guard.hpp"

namespace lookahead::slam {
namespace {

using mrpt::serialization::CSerializable;

/// A record that deserialised but cannot be used. The stream already sits at the next
/// record, so unlike a deserialisation failure this one can be skipped.
struct BadRecord {
  std::string field;
  std::string value;
  std::string reason;
};

/// MRPT exception texts are a banner, a "Message:" line, the location and a call trace;
/// only the message belongs in a ParseError.
std::string mrpt_message(const std::string& text) {
  const std::string tag = "Message:";
  auto begin = text.find(tag);
  begin = begin == std::string::npos ? 0 : text.find_first_not_of(' ', begin + tag.size());
  if (begin == std::string::npos) begin = 0;
  const auto end = text.find('\n', begin);
  std::string message = text.substr(begin, end == std::string::npos ? end : end - begin);
  // Garbage input puts random bytes into "class '...' is not registered"; keep logs printable.
  for (char& c : message) {
    if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) > 0x7e) c = '?';
  }
  return message;
}

Pose2 to_pose2(const mrpt::poses::CPose2D& p) { return {p.x(), p.y(), normalize_angle(p.phi())}; }

class RawlogReader {
 public:
  RawlogReader(const LogReadOptions& options, LaserLog& log) : options_(options), log_(log) {}

  void set_record(std::size_t record) { record_ = record; }

  /// Dispatches one top-level object of the file.
  void on_object(const CSerializable::Ptr& object) {
    if (!object) throw BadRecord{"record", "nullptr", "empty object in the stream"};
    count(object->GetRuntimeClass()->className);
    if (const auto actions = std::dynamic_pointer_cast<mrpt::obs::CActionCollection>(object)) {
      on_actions(*actions);
    } else if (const auto frame = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(object)) {
      // Odometry of the pair layout comes from the actions; an odometry reading inside a
      // frame would count the same motion twice.
      for (const auto& obs : *frame) on_observation(obs, /*use_odometry=*/false);
    } else if (const auto obs = std::dynamic_pointer_cast<mrpt::obs::CObservation>(object)) {
      on_observation(obs, /*use_odometry=*/true);
    } else if (const auto nested = std::dynamic_pointer_cast<mrpt::obs::CRawlog>(object)) {
      // Some writers serialise a whole CRawlog as one object; its entries are the records.
      for (std::size_t i = 0; i < nested->size(); ++i) on_object(nested->getAsGeneric(i));
    } else {
      throw BadRecord{"class", object->GetRuntimeClass()->className, "not an action, sensory frame or observation"};
    }
  }

 private:
  void on_actions(const mrpt::obs::CActionCollection& actions) {
    const auto move = actions.getActionByClass<mrpt::obs::CActionRobotMovement2D>();
    if (!move) return;  // e.g. a 3D or unrelated action: the robot did not report 2D motion
    if (!move->poseChange) throw BadRecord{"poseChange", "", "2D movement without a pose"};
    // The increment is relative to the previous frame, so it composes on the robot side.
    odometry_ = odometry_.compose(to_pose2(move->poseChange->getMeanVal()));
  }

  void on_observation(const mrpt::obs::CObservation::Ptr& obs, bool use_odometry) {
    if (!obs) return;
    if (!use_odometry) count(obs->GetRuntimeClass()->className);  // inside a sensory frame
    if (const auto odo = std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(obs)) {
      // Rawlogs are written in time order, so the last reading seen is the latest one at or
      // before any scan that follows it; a scan with none yet keeps the previous pose.
      if (use_odometry) odometry_ = to_pose2(odo->odometry);
      return;
    }
    if (const auto scan = std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(obs)) {
      log_.scans.push_back(to_scan(*scan));
    }
    // Other sensors (cameras, GPS, ...) are not used by the filter and are skipped.
  }

  void count(const std::string& kind) {
    for (MessageCount& m : log_.messages) {
      if (m.type == kind) {
        ++m.count;
        return;
      }
    }
    log_.messages.push_back({"", kind, 1});
  }

  LaserScan to_scan(const mrpt::obs::CObservation2DRangeScan& obs) const {
    const std::size_t n = obs.getScanSize();
    if (n < 2) throw BadRecord{"scan size", std::to_string(n), "a scan needs at least 2 beams"};
    if (!(obs.aperture > 0.0f) || !std::isfinite(obs.aperture)) {
      throw BadRecord{"aperture", std::to_string(obs.aperture), "aperture must be positive"};
    }
    LaserScan scan;
    double stamp = mrpt::Clock::toDouble(obs.timestamp);
    // INVALID_TIMESTAMP converts to 0.0: such logs get a synthetic 10 Hz clock from the
    // record index, which keeps them in order (not real time, so do not mix with real stamps).
    if (!(stamp > 0.0)) stamp = static_cast<double>(record_) * 0.1;
    scan.timestamp = stamp;
    scan.logger_timestamp = stamp;  // one clock in a rawlog
    scan.angle_min = -0.5 * obs.aperture;
    scan.angle_increment = obs.aperture / static_cast<double>(n - 1);
    scan.max_range = obs.maxRange;
    scan.laser_offset = {obs.sensorPose.x(), obs.sensorPose.y(), normalize_angle(obs.sensorPose.yaw())};
    scan.odometry = odometry_;
    scan.source_line = record_;
    // MRPT reads this flag as a byte straight from the file, so a corrupt file can leave a
    // value in it that is no bool; its byte is read as what it is.
    unsigned char right_to_left = 0;
    static_assert(sizeof obs.rightToLeft == sizeof right_to_left);
    std::memcpy(&right_to_left, &obs.rightToLeft, sizeof right_to_left);
    if (right_to_left > 1) {
      throw BadRecord{"rightToLeft", std::to_string(right_to_left), "the scan direction must be 0 or 1"};
    }
    scan.ranges.resize(n);
    constexpr float no_return = std::numeric_limits<float>::infinity();
    for (std::size_t i = 0; i < n; ++i) {
      const float r = obs.getScanRange(i);
      const bool valid = obs.getScanRangeValidity(i) && r < options_.no_return_range;
      // A left-to-right scanner sweeps clockwise; storing it reversed keeps beams CCW from
      // angle_min, which is what every consumer of LaserScan assumes.
      const std::size_t slot = right_to_left != 0 ? i : n - 1 - i;
      scan.ranges[slot] = valid ? r : no_return;
    }
    return scan;
  }

  const LogReadOptions& options_;
  LaserLog& log_;
  Pose2 odometry_;  // the pair layout starts its accumulated odometry at the origin
  std::size_t record_ = 0;
};

/// Books one bad record; returns normally only if the caller asked to skip bad records.
void handle_bad(LaserLog& log, const LogReadOptions& options, std::size_t record, const BadRecord& bad) {
  ParseError error(log.path, record, bad.field, bad.value, bad.reason);
  if (!options.skip_bad_lines) throw error;
  if (log.bad_lines == 0) log.first_bad_line_message = error.what();
  ++log.bad_lines;
}

/// Reads records until a clean end of file, or until the stream breaks.
void read_records(mrpt::serialization::CArchive& archive, RawlogReader& reader, LaserLog& log,
                  const LogReadOptions& options) {
  for (std::size_t record = 1;; ++record) {
    CSerializable::Ptr object;
    try {
      object = archive.ReadObject();
    } catch (const mrpt::serialization::CExceptionEOF&) {
      return;  // MRPT's signal for an end of file between two objects
    } catch (const std::exception& e) {
      // Nothing after a broken object can be trusted: a truncated or corrupt file ends here.
      // What came before it is mapped; with no scan yet the file is not a rawlog at all.
      const std::string reason = "cannot deserialise: " + mrpt_message(e.what());
      log.lines_read = record;
      if (log.scans.empty()) handle_bad(log, options, record, {"record", "", reason});
      log.stopped_early = ParseError(log.path, record, "record", "", reason).what();
      return;
    }
    log.lines_read = record;
    reader.set_record(record);
    try {
      reader.on_object(object);
    } catch (const BadRecord& bad) {
      handle_bad(log, options, record, bad);
    } catch (const std::exception& e) {
      // An MRPT assertion on an object that did deserialise: the stream itself is intact.
      handle_bad(log, options, record, {"record", "", "MRPT error: " + mrpt_message(e.what())});
    }
  }
}

}  // namespace

LaserLog detail::read_mrpt_rawlog_unguarded(const std::string& path, const LogReadOptions& options) {
  LaserLog log;
  log.path = path;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    throw ParseError(path, 0, "", "", "no such file (or not a regular file)");
  }
  // CFileGZInputStream reads both gzip-compressed and plain rawlogs transparently.
  mrpt::io::CFileGZInputStream stream;
  std::string open_error;
  try {
    if (!stream.open(path, open_error)) {
      throw ParseError(path, 0, "", "", "cannot open: " + mrpt_message(open_error));
    }
  } catch (const ParseError&) {
    throw;
  } catch (const std::exception& e) {
    throw ParseError(path, 0, "", "", "cannot open: " + mrpt_message(e.what()));
  }
  auto archive = mrpt::serialization::archiveFrom(stream);
  RawlogReader reader(options, log);
  // A broken stream ends the read; with skip_bad_lines what came before it is kept.
  read_records(archive, reader, log, options);
  log.scan_source = "CObservation2DRangeScan";
  log.odometry_source = "CActionRobotMovement2D or CObservationOdometry";
  check_odometry(log, options);
  return log;
}

}  // namespace lookahead::slam
