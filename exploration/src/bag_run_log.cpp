// SPDX-License-Identifier: MIT
#include "lookahead/exploration/bag_run_log.hpp"

#include "lookahead/exploration/carmen_writer.hpp"

namespace lookahead::exploration {

BagRunLog::BagRunLog(const std::string& path, const LaserOptions& laser) : writer_((laser.validate(), path)) {}

void BagRunLog::odometry(const slam::Pose2& odom, double /*tv*/, double /*rv*/, double t) { writer_.odometry(t, odom); }

void BagRunLog::scan(const slam::LaserScan& scan) { writer_.scan(scan); }

void BagRunLog::true_pose(const slam::Pose2& truth, const slam::Pose2& /*odom*/, double t) {
  writer_.ground_truth(t, truth);
}

void BagRunLog::close() { writer_.close(); }

std::unique_ptr<RunLog> open_run_log(const std::string& path, const LaserOptions& laser) {
  const bool bag = path.size() >= 4 && path.compare(path.size() - 4, 4, ".bag") == 0;
  if (bag) return std::make_unique<BagRunLog>(path, laser);
  return std::make_unique<CarmenWriter>(path, laser);
}

}  // namespace lookahead::exploration
