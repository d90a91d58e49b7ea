// SPDX-License-Identifier: MIT
// Bag messages deserialised only after their array lengths were checked against the size of
// the message. ROS's generated deserialisers resize a vector to the length the bytes declare
// before they read it (ros/serialization.h), so one corrupted length field asks for up to
// 16 GB; here such a message is an error naming the array, its length and the bytes there are.
#pragma once

#include <rosbag/message_instance.h>
#include <sensor_msgs/LaserScan.h>
#include <tf2_msgs/TFMessage.h>

#include <boost/shared_ptr.hpp>

namespace lookahead::slam {

/// The scan, nullptr for a message of another type; throws std::runtime_error when an array
/// length does not fit the message.
boost::shared_ptr<sensor_msgs::LaserScan> read_scan_message(const rosbag::MessageInstance& message);
/// The transforms, as read_scan_message.
boost::shared_ptr<tf2_msgs::TFMessage> read_tf_message(const rosbag::MessageInstance& message);

}  // namespace lookahead::slam
