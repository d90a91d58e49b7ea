// SPDX-License-Identifier: MIT
#include "bag_message.hpp"

#include <fmt/format.h>
#include <ros/serialization.h>

#include <boost/make_shared.hpp>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace lookahead::slam {
namespace {

// The smallest serialised geometry_msgs/TransformStamped: a header (seq, stamp, empty
// frame_id), an empty child_frame_id and seven float64.
constexpr std::uint64_t kMinTransformBytes = 3 * 4 + 4 + 4 + 7 * 8;

std::vector<std::uint8_t> bytes_of(const rosbag::MessageInstance& message) {
  std::vector<std::uint8_t> bytes(message.size());
  ros::serialization::OStream out(bytes.data(), static_cast<std::uint32_t>(bytes.size()));
  message.write(out);
  return bytes;
}

// Walks a serialised message (little-endian, as ROS writes it) only as far as needed to
// check the lengths it declares against the bytes that follow them.
class LengthCheck {
 public:
  LengthCheck(const rosbag::MessageInstance& message, const std::vector<std::uint8_t>& bytes)
      : message_(message), bytes_(bytes) {}

  void skip(std::uint64_t n, const char* field) {
    if (n > left()) fail(field, n, 1);
    at_ += n;
  }
  void string(const char* field) { skip(length(field), field); }
  void array(const char* field, std::uint64_t element_bytes) {
    at_ += array_head(field, element_bytes) * element_bytes;
  }
  /// The length of an array whose elements are at least `min_element_bytes` each, checked;
  /// its elements are not walked.
  std::uint64_t array_head(const char* field, std::uint64_t min_element_bytes) {
    const std::uint64_t n = length(field);
    if (n * min_element_bytes > left()) fail(field, n, min_element_bytes);
    return n;
  }
  void header() {
    skip(3 * 4, "header");  // seq, stamp
    string("header.frame_id");
  }

 private:
  std::uint64_t left() const { return bytes_.size() - at_; }
  std::uint64_t length(const char* field) {
    if (left() < 4) fail(field, 4, 1);
    std::uint32_t n = 0;
    std::memcpy(&n, bytes_.data() + at_, 4);
    at_ += 4;
    return n;
  }
  [[noreturn]] void fail(const char* field, std::uint64_t n, std::uint64_t element_bytes) const {
    throw std::runtime_error(
        fmt::format("the {} message at t = {:.6f} s on {} is corrupt: its {} declares {} x {} bytes where {} of its {} "
                    "bytes are left",
                    message_.getDataType(), message_.getTime().toSec(), message_.getTopic(), field, n, element_bytes,
                    left(), bytes_.size()));
  }

  const rosbag::MessageInstance& message_;
  const std::vector<std::uint8_t>& bytes_;
  std::uint64_t at_ = 0;
};

template <class Message>
boost::shared_ptr<Message> deserialise(std::vector<std::uint8_t>& bytes) {
  auto m = boost::make_shared<Message>();
  ros::serialization::IStream in(bytes.data(), static_cast<std::uint32_t>(bytes.size()));
  ros::serialization::deserialize(in, *m);
  return m;
}

}  // namespace

boost::shared_ptr<sensor_msgs::LaserScan> read_scan_message(const rosbag::MessageInstance& message) {
  if (!message.isType<sensor_msgs::LaserScan>()) return nullptr;
  std::vector<std::uint8_t> bytes = bytes_of(message);
  LengthCheck check(message, bytes);
  check.header();
  check.skip(7 * 4, "angles and ranges");  // angle_min .. range_max
  check.array("ranges", 4);
  check.array("intensities", 4);
  return deserialise<sensor_msgs::LaserScan>(bytes);
}

boost::shared_ptr<tf2_msgs::TFMessage> read_tf_message(const rosbag::MessageInstance& message) {
  if (!message.isType<tf2_msgs::TFMessage>()) return nullptr;
  std::vector<std::uint8_t> bytes = bytes_of(message);
  LengthCheck(message, bytes).array_head("transforms", kMinTransformBytes);
  return deserialise<tf2_msgs::TFMessage>(bytes);
}

}  // namespace lookahead::slam
