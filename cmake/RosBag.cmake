# SPDX-License-Identifier: MIT
# ROS1 bag storage and message headers from Debian (librosbag-storage-dev, libsensor-msgs-dev,
# libnav-msgs-dev, libtf2-msgs-dev). Debian's rosbag_storage.pc requires a pluginlib.pc that
# the ROS 2 pluginlib package does not ship, so the target is assembled here.
# Provides lookahead::ros_bag (INTERFACE, headers as SYSTEM so our warnings stay ours).
find_path(LOOKAHEAD_ROSBAG_INCLUDE rosbag/bag.h REQUIRED)
find_path(LOOKAHEAD_LASERSCAN_INCLUDE sensor_msgs/LaserScan.h REQUIRED)
find_path(LOOKAHEAD_ODOMETRY_INCLUDE nav_msgs/Odometry.h REQUIRED)
find_path(LOOKAHEAD_TFMESSAGE_INCLUDE tf2_msgs/TFMessage.h REQUIRED)
set(_ros_bag_libs)
foreach(lib rosbag_storage roslz4 rostime cpp_common roscpp_serialization console_bridge class_loader boost_filesystem)
  find_library(LOOKAHEAD_LIB_${lib} ${lib} REQUIRED)
  list(APPEND _ros_bag_libs ${LOOKAHEAD_LIB_${lib}})
endforeach()
add_library(lookahead_ros_bag INTERFACE)
add_library(lookahead::ros_bag ALIAS lookahead_ros_bag)
# rosbag/bag.h includes pluginlib, which includes class_loader, rcpputils and rcutils.
target_include_directories(lookahead_ros_bag SYSTEM INTERFACE
  ${LOOKAHEAD_ROSBAG_INCLUDE} /usr/include/pluginlib /usr/include/class_loader
  /usr/include/rcpputils /usr/include/rcutils /usr/include/ament_index_cpp)
target_link_libraries(lookahead_ros_bag INTERFACE ${_ros_bag_libs})
