// SPDX-License-Identifier: MIT
// A study's progress as a log file a user can `tail -f` (on a cluster, where no terminal
// shows a bar): one line per finished mission with the count done, the missions in flight
// and the estimated time left (the mean wall time per finished mission so far times the
// missions left, the workers already accounted for in the elapsed wall time).
#pragma once

#include <fstream>
#include <string>

#include "lookahead/exploration/study.hpp"

namespace lookahead::app {

class StudyProgressLog {
 public:
  /// Appends to `path` (its folder is made); `what` names the share ("shard 2/8", "all").
  StudyProgressLog(const std::string& path, std::string what);
  void update(const exploration::StudyProgress& p);
  [[nodiscard]] const std::string& path() const { return path_; }

 private:
  std::string path_, what_;
  std::ofstream out_;
};

/// "1 h 05 min", "3 min 20 s", "12 s"
std::string format_duration(double seconds);

}  // namespace lookahead::app
