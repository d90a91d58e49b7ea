// SPDX-License-Identifier: MIT
// A forbidden include: the dependency rules must reject this tree.
#include "lookahead/slam/segslam/seg_slam.hpp"
