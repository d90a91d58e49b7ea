// SPDX-License-Identifier: MIT
// The YAML loaders of mission, slam (RBPF), SegSLAM and study files; the first byte picks
// the loader, the rest is the file.
#include <exception>
#include <string>

#include "lookahead/exploration/mission_config.hpp"
#include "lookahead/exploration/study_config.hpp"
#include "lookahead/slam/rbpf/slam_config.hpp"
#include "lookahead/slam/segslam/segslam_config.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string yaml(reinterpret_cast<const char*>(data) + 1, size - 1);
  try {
    switch (data[0] % 4) {
      case 0:
        (void)lookahead::exploration::parse_mission_options(yaml, "fuzz.yaml");
        break;
      case 1:
        (void)lookahead::slam::parse_rbpf_options(yaml, "fuzz.yaml");
        break;
      case 2:
        (void)lookahead::slam::parse_segslam_options(yaml, "fuzz.yaml");
        break;
      default:
        (void)lookahead::exploration::parse_study(yaml, "fuzz.yaml", "/tmp");
        break;
    }
  } catch (const std::exception&) {
  }
  return 0;
}
