// SPDX-License-Identifier: MIT
// The bounds every input size and option value is checked against before work starts, and
// the memory check of what a run is about to allocate. Each bound is far above what a real
// robot, log or world needs and far below what would run for hours or exhaust memory;
// docs/limits.md gives each value's reason.
#pragma once

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace lookahead::slam::limits {

/// Beams in one scan: 10x a 0.1-degree 360-degree scanner (3600).
inline constexpr std::size_t kMaxBeams = 100000;
/// Laser and likelihood range [m]: 4x the longest planar lidar (250 m); every ray walks
/// range / resolution cells, so 10^9 m would take hours per beam.
inline constexpr double kMaxLaserRange = 1000.0;
/// Motion-noise coefficients (srr, srt, str, stt): 10 m (or rad) of error per metre (or
/// radian) of motion is already noise without information.
inline constexpr double kMaxMotionNoise = 10.0;
/// Entries of one grid's tile table (16 bytes each, one table per particle): 2^21 is a
/// 2.3 km square at 5 cm (GridTile::kSide 32 cells) and 32 MB per grid.
inline constexpr std::int64_t kMaxGridTiles = std::int64_t{1} << 21;
/// Pixels of a world or map image: 8192 x 8192 (a 410 m square at 5 cm).
inline constexpr std::int64_t kMaxImagePixels = std::int64_t{1} << 26;
/// Nesting depth of blocks in a Stage .world file (real worlds nest 2-4 deep).
inline constexpr int kMaxWorldNesting = 64;
/// Runs of one study (worlds x variants x seeds).
inline constexpr std::size_t kMaxStudyRuns = 100000;

/// A run that would need more than the machine has: names the need and what is there.
class ResourceLimitError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Bytes this process may still allocate: MemAvailable of /proc/meminfo, lowered to the
/// address-space limit (RLIMIT_AS) when one is set.
[[nodiscard]] std::uint64_t available_memory_bytes();

/// Throws ResourceLimitError when `bytes` exceeds available_memory_bytes(); the message
/// names `what` (e.g. "100000 particles x 212 tiles of 4.2 KB") and both sizes.
void check_memory(double bytes, const std::string& what);

}  // namespace lookahead::slam::limits
