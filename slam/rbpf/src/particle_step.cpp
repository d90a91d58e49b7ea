// SPDX-License-Identifier: MIT
#include "lookahead/slam/rbpf/particle_step.hpp"

#include "lookahead/slam/rbpf/improved_proposal.hpp"
#include "lookahead/slam/sensor/scan_inserter.hpp"

namespace lookahead::slam {

bool draw_particle(const ParticleStepModels& m, const OccupancyGrid& map, Pose2& pose, double& log_weight,
                   const Pose2& u, const PreparedScan& prepared, bool warm, std::mt19937_64& rng, Pose2* estimate) {
  const bool match_scan = warm && m.options.proposal.kind == ProposalKind::kScanMatch;
  // The particles' spread enters before the match, as a motion-model draw of its start
  // (GMapping's released code), not as a draw around it (improved_proposal.hpp).
  const Pose2 start = match_scan ? m.motion.sample(pose, u, rng) : pose.compose(u);
  MatchResult match;
  if (match_scan) match = m.matcher.match(map, start, prepared, m.motion.rotation_sigma(u));
  bool failed = false;
  if (match_scan && match.ok) {
    const ProposalMean d = improved_proposal(map, pose, u, match.pose, prepared, m.likelihood, m.motion,
                                             m.options.proposal, FieldLookup::kBilinear);
    pose = d.mean;
    if (estimate) *estimate = d.mean;
    log_weight += m.options.weight_exponent * d.log_eta;
  } else {
    // The motion-model proposal, chosen or where scan matching fails (as Grisetti et al. do):
    // sample the odometry model and weight by the observation.
    pose = m.motion.sample(pose, u, rng);
    if (estimate) *estimate = pose;
    if (warm) log_weight += m.options.weight_exponent * m.likelihood.log_likelihood(map, pose, prepared);
    failed = match_scan;
  }
  return failed;
}

bool advance_particle(const ParticleStepModels& m, OccupancyGrid& map, Pose2& pose, double& log_weight, const Pose2& u,
                      const LaserScan& scan, const PreparedScan& prepared, bool warm, std::mt19937_64& rng) {
  const bool failed = draw_particle(m, map, pose, log_weight, u, prepared, warm, rng);
  insert_scan(map, pose, scan, m.options.insert);
  return failed;
}

std::uint64_t mix_seed(std::uint64_t a, std::uint64_t b, std::uint64_t c) {
  std::uint64_t z = a ^ (b * 0x9E3779B97F4A7C15ull) ^ (c * 0xC2B2AE3D27D4EB4Full);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

}  // namespace lookahead::slam
