// SPDX-License-Identifier: MIT
#include "lookahead/predictor/registration.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

namespace lookahead::predictor {
namespace {

// The reference corners to try: all but the control point's own, at most the cap (a seeded
// random subset beyond it: the paper's fixed search bound, sec. III-A).
std::vector<const Corner*> reference_corners(const Corner& control, const std::vector<Corner>& corners,
                                             const PredictorOptions& o) {
  std::vector<const Corner*> out;
  for (const Corner& c : corners) {
    if (std::hypot(c.x - control.x, c.y - control.y) >= o.min_reference_distance) out.push_back(&c);
  }
  const auto cap = static_cast<std::size_t>(o.max_reference_corners);
  if (out.size() > cap) {
    std::mt19937_64 rng(o.seed);
    std::shuffle(out.begin(), out.end(), rng);
    out.resize(cap);
  }
  return out;
}

// Psi decides; alignments within a hundredth of each other are equally good (a symmetric
// building has several), and the one that predicts more of the unexplored region wins.
bool better(const SimilarityScore& a, const SimilarityScore& b) {
  constexpr double kTie = 0.01;
  return a.psi > b.psi + kTie || (a.psi >= b.psi - kTie && a.new_known > b.new_known);
}

// Every k-th sample of a region: a quarter of the samples estimates Psi to within a few
// hundredths, enough to tell the few alignments worth scoring in full.
RegionSamples thinned(const RegionSamples& r, std::size_t k) {
  RegionSamples out;
  for (std::size_t i = 0; i < r.x.size(); i += k) {
    out.x.push_back(r.x[i]);
    out.y.push_back(r.y[i]);
  }
  return out;
}

// Alignments whose Psi on the thinned samples falls this far below the threshold are not
// scored in full: most of the hundreds tried are nowhere near it.
constexpr double kScreenMargin = 0.15;

}  // namespace

std::array<slam::Pose2, 4> corner_alignments(const Corner& control, const Corner& reference) {
  const double p1[2] = {control.angle_a, control.angle_b};
  const double p2[2] = {reference.angle_a, reference.angle_b};
  std::array<slam::Pose2, 4> out;
  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j < 2; ++j) {
      const double theta = slam::normalize_angle(p1[i] - p2[j]);
      const double c = std::cos(theta), s = std::sin(theta);
      // Rotate about P2, then move P2 onto P1.
      out[static_cast<std::size_t>(2 * i + j)] = {control.x - (c * reference.x - s * reference.y),
                                                  control.y - (s * reference.x + c * reference.y), theta};
    }
  }
  return out;
}

Registration register_region(const CoarseOccupancy& map, const RegionSamples& target_region, const Corner& control,
                             const std::vector<Corner>& corners, const PredictorOptions& o) {
  Registration r;
  const double min_new = o.min_predicted_area / (map.resolution() * map.resolution());
  const TargetRegion target(map, target_region);
  const TargetRegion screen(map, thinned(target_region, 4));
  std::optional<Alignment> best_screened_out;  // reported only when no alignment passes
  for (const Corner* ref : reference_corners(control, corners, o)) {
    for (const slam::Pose2& t : corner_alignments(control, *ref)) {
      ++r.candidates;
      const SimilarityScore quick = similarity(screen, map, t);
      if (quick.psi < o.similarity_threshold - kScreenMargin) {
        if (!best_screened_out || quick.psi > best_screened_out->score.psi)
          best_screened_out = Alignment{t, control, *ref, quick};
        continue;
      }
      const SimilarityScore s = similarity(target, map, t);
      if (s.new_known < min_new) continue;                      // explains explored cells only: predicts nothing
      if (s.conflict_share() > o.max_conflict_share) continue;  // walls across known free space
      if (!r.best || better(s, r.best->score)) r.best = Alignment{t, control, *ref, s};
    }
  }
  if (!r.best) r.best = best_screened_out;  // below the threshold either way: no hypothesis
  return r;
}

}  // namespace lookahead::predictor
