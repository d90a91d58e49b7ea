// SPDX-License-Identifier: MIT
// A bag whose recording was interrupted has no index (rosbag writes it when the bag is
// closed), and rosbag_storage refuses to open it. ROS's own `rosbag reindex` (Debian
// python3-rosbag) rebuilds the index from the chunks that were written completely; the
// messages of the last, partial chunk are lost. The copy goes to a temporary folder: the
// user's file is never modified.
#pragma once

#include <string>

namespace lookahead::slam {

/// A reindexed copy of a bag, removed with this object.
class ReindexedBag {
 public:
  /// Runs `rosbag reindex` on `path` into a fresh temporary folder. Throws ParseError naming
  /// `path` and why when the tool is missing or cannot rebuild the index.
  explicit ReindexedBag(const std::string& path);
  ~ReindexedBag();
  ReindexedBag(const ReindexedBag&) = delete;
  ReindexedBag& operator=(const ReindexedBag&) = delete;

  const std::string& path() const { return copy_; }

 private:
  std::string folder_;
  std::string copy_;
};

}  // namespace lookahead::slam
