// SPDX-License-Identifier: MIT
#include "correspondence_vote.hpp"

#include <map>

namespace lookahead::slam::hybrid {
namespace {

// The options of one observation: gamma >= 0 for "associate with common feature gamma",
// kSpurious, kNew.
constexpr long kSpurious = -1;
constexpr long kNew = -2;

long option_of(const Particle& p, const Decision& d) {
  switch (d.kind) {
    case Decision::Kind::kSpurious:
      return kSpurious;
    case Decision::Kind::kCreated:
      return kNew;
    case Decision::Kind::kAssociated: {
      const long id = p.landmarks[static_cast<std::size_t>(d.landmark)].id;
      return id >= 0 ? id : kNew;  // an unidentified landmark votes like a new one
    }
  }
  return kSpurious;
}

long winner_of(const std::vector<Particle>& particles, const std::vector<std::vector<Decision>>& decisions,
               std::size_t j) {
  std::map<long, double> tally;  // ordered: ties go to the smallest option, deterministically
  for (std::size_t p = 0; p < particles.size(); ++p) {
    tally[option_of(particles[p], decisions[p][j])] += particles[p].weight;
  }
  long best = kSpurious;
  double best_weight = -1.0;
  for (const auto& [option, weight] : tally) {
    if (weight > best_weight) best = option, best_weight = weight;
  }
  return best;
}

}  // namespace

std::vector<long> vote_correspondences(std::vector<Particle>& particles,
                                       const std::vector<std::vector<Decision>>& decisions, long& next_id) {
  const std::size_t n_obs = decisions.empty() ? 0 : decisions.front().size();
  std::vector<long> winners(n_obs, -1);
  for (std::size_t j = 0; j < n_obs; ++j) {
    const long won = winner_of(particles, decisions, j);
    // "Spurious" won: there is no winning gamma. Deviation (the paper leaves this case
    // open): landmarks the minority created still need one common identity, so they share a
    // fresh one; landmarks a minority updated keep theirs.
    const long gamma = won >= 0 ? won : next_id++;
    winners[j] = won == kSpurious ? -1 : gamma;
    for (std::size_t p = 0; p < particles.size(); ++p) {
      const Decision& d = decisions[p][j];
      if (d.kind == Decision::Kind::kSpurious) continue;
      Landmark& l = particles[p].landmarks[static_cast<std::size_t>(d.landmark)];
      if (won != kSpurious || d.kind == Decision::Kind::kCreated || l.id < 0) l.id = gamma;
    }
  }
  return winners;
}

}  // namespace lookahead::slam::hybrid
