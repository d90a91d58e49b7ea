// SPDX-License-Identifier: MIT
// YAML configuration of HybridSLAM: the filter, the simulation, the study and the scan
// landmarks of real logs, in one file
// (config/hybrid/default.yaml). Unknown keys and bad values are ParseErrors naming the
// file, the line, the key and the value.
#pragma once

#include <string>

#include "lookahead/slam/hybrid/hybrid_options.hpp"
#include "lookahead/slam/hybrid/scan_landmarks.hpp"
#include "lookahead/slam/hybrid/simulation.hpp"
#include "lookahead/slam/hybrid/study.hpp"

namespace lookahead::slam::hybrid {

struct HybridConfig {
  HybridOptions filter;
  SimulationOptions simulation;
  StudyOptions study;
  ScanLandmarkOptions scan_landmarks;  ///< real logs only (`slam --method hybrid`)
};

HybridConfig load_hybrid_config(const std::string& path, const HybridConfig& base = {});
/// For `slam --method hybrid`: as load_hybrid_config, but a file with a `simulation` or
/// `study` section (a hybrid-sim file) is refused with its file and line.
HybridConfig load_hybrid_log_config(const std::string& path, const HybridConfig& base);
HybridConfig parse_hybrid_config(const std::string& yaml, const std::string& source, const HybridConfig& base = {});
/// Every option with its default and unit (`lookahead config dump hybrid`).
std::string dump_hybrid_config(const HybridConfig& config);

}  // namespace lookahead::slam::hybrid
