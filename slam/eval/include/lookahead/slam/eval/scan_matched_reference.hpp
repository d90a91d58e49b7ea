// SPDX-License-Identifier: MIT
// A reference trajectory for a raw log from a corrected log whose timestamps cannot be
// paired with it (the Radish csail.corrected.log prints 6 significant digits, i.e. the
// same stamp for the whole run, and keeps only every ~5th scan). Each corrected scan is
// paired with the raw scan that has the same range readings, and its corrected pose is
// stamped with that raw scan's logger time, so relative_error() and
// absolute_trajectory_error() can score a trajectory of the raw log against it.
#pragma once

#include <vector>

#include "lookahead/slam/io/laser_log.hpp"
#include "lookahead/slam/io/trajectory_io.hpp"

namespace lookahead::slam {

struct ScanMatchedReference {
  std::vector<StampedPose> poses;  ///< corrected poses on the raw log's logger clock
  std::size_t unmatched = 0;       ///< corrected scans with no raw scan close enough
};

/// Pairs by the mean absolute range difference over the beams both scans have, which must
/// be at most `tolerance` [m] (the two logs round readings differently). Raw scans are
/// searched forward from the previous pair, so the reference keeps the raw log's order.
ScanMatchedReference reference_by_matching_scans(const LaserLog& corrected, const LaserLog& raw,
                                                 double tolerance = 0.01);

}  // namespace lookahead::slam
