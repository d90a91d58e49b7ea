// SPDX-License-Identifier: MIT
// When look-ahead mapping covers a frontier, so that a predictive strategy skips it (P-SLAM
// sec. II-B: "the robot can decide not to explore the predicted regions"): the rule, and the
// frontier's unexplored region it is judged on (region_flood.hpp finds it).
#pragma once

#include <array>
#include <optional>
#include <utility>

namespace lookahead::exploration {

/// Which frontiers look-ahead mapping covers, so that a predictive strategy skips them
/// (P-SLAM sec. II-B: "the robot can decide not to explore the predicted regions").
enum class SkipVariant {
  kFarSide,  ///< the share of unknown cells beside the frontier that is predicted (covered_share)
  kRegion,   ///< its unexplored region within region_radius is predicted (region_area)
};

/// lookahead.skip in YAML (a named choice, slam/config/named_choice.hpp).
constexpr std::array<std::pair<SkipVariant, const char*>, 2> choice_names(SkipVariant) {
  return {{{SkipVariant::kFarSide, "far_side"}, {SkipVariant::kRegion, "region"}}};
}

/// When look-ahead mapping covers a frontier (LookaheadOptions has the meaning of each).
struct SkipRule {
  double min_confidence = 0.6;  ///< hypotheses below this Psi do not count
  SkipVariant variant = SkipVariant::kFarSide;
  double region_radius = 7.0;     ///< kRegion: the region's reach from the goal [m], > 0
  double region_tolerance = 1.0;  ///< ... covered up to this much unpredicted area [m^2]
  double occupied = 0.65;         ///< predicted walls: probability at least this
  /// kRegion: unknown gaps up to this wide in a wall (explored or predicted)
  /// close the region as the wall would [m]; 0: only unbroken walls close it.
  double wall_gap = 0.0;
  /// kRegion: the environment's boundary, when known (P-SLAM Fig. 7(d)): no
  /// region reaches beyond it, where nothing can be explored or predicted [m].
  struct Extent {
    double min_x, min_y, max_x, max_y;
  };
  std::optional<Extent> boundary;
  /// kRegion: also leave out wall slivers, frontiers whose unexplored region is a
  /// closed pocket (RegionArea::wall_sliver): a wall seen at a grazing angle, a corner seen
  /// from afar, a gap into a pillar. Their region then also holds the cells seen but
  /// undecided (probability in [free, occupied)), as the frontier detector counts them
  /// unexplored: a band of such cells alone makes a frontier, and without them in its
  /// region the frontier would look empty, not closed, and the robot would drive to it.
  bool skip_wall_slivers = false;
  double free = 0.35;  ///< with skip_wall_slivers: a seen cell below this is explored

  // Construction by name: SkipRule::region(7.0).with_region_tolerance(1.0).with_wall_gap(0.4).
  /// The region variant reaching `radius` [m] from the goal, other fields at their defaults.
  [[nodiscard]] static SkipRule region(double radius) {
    return SkipRule{}.with_variant(SkipVariant::kRegion).with_region_radius(radius);
  }
  /// The far-side variant, other fields at their defaults.
  [[nodiscard]] static SkipRule far_side() { return SkipRule{}.with_variant(SkipVariant::kFarSide); }
  [[nodiscard]] SkipRule with_min_confidence(double v) const { return with(&SkipRule::min_confidence, v); }
  [[nodiscard]] SkipRule with_variant(SkipVariant v) const { return with(&SkipRule::variant, v); }
  [[nodiscard]] SkipRule with_region_radius(double v) const { return with(&SkipRule::region_radius, v); }
  [[nodiscard]] SkipRule with_region_tolerance(double v) const { return with(&SkipRule::region_tolerance, v); }
  [[nodiscard]] SkipRule with_occupied(double v) const { return with(&SkipRule::occupied, v); }
  [[nodiscard]] SkipRule with_wall_gap(double v) const { return with(&SkipRule::wall_gap, v); }
  [[nodiscard]] SkipRule with_boundary(std::optional<Extent> v) const { return with(&SkipRule::boundary, v); }
  [[nodiscard]] SkipRule with_wall_slivers(bool v) const { return with(&SkipRule::skip_wall_slivers, v); }
  [[nodiscard]] SkipRule with_free(double v) const { return with(&SkipRule::free, v); }

 private:
  template <typename T, typename V>
  [[nodiscard]] SkipRule with(T SkipRule::*field, V value) const {
    SkipRule copy = *this;
    copy.*field = std::move(value);
    return copy;
  }
};

/// A frontier's unexplored region (PredictedMap::region_area) [m^2].
struct RegionArea {
  double predicted = 0.0;             ///< by a hypothesis with the minimum Psi
  double unpredicted = 0.0;           ///< what driving there would still reveal
  bool closed_by_prediction = false;  ///< a predicted wall bounds it
  /// An unexplored cell within the radius was left out of it: in a wall gap or beyond the boundary.
  bool closed_by_gap = false;
  /// ... in a gap that only a predicted wall closes (counted with SkipRule::skip_wall_slivers).
  bool gap_of_prediction = false;
  /// Something of it is predicted: a predicted part or a predicted wall closing it. An
  /// empty region (the far side already seen) is not left out by any prediction.
  [[nodiscard]] bool touched_by_prediction() const { return predicted > 0 || closed_by_prediction; }
  /// Left out by look-ahead mapping: touched by a prediction, and at most `tolerance` of it
  /// is not predicted [m^2].
  [[nodiscard]] bool covered(double tolerance) const { return touched_by_prediction() && unpredicted <= tolerance; }
  /// A wall sliver: a closed pocket no prediction touches (nor closes by a gap), of at most
  /// `tolerance` [m^2], with something unexplored in it or left out of it as a wall gap or
  /// beyond the boundary.
  /// Not the empty region of a stale frontier, whose far side was seen since (nothing
  /// unexplored at all).
  [[nodiscard]] bool wall_sliver(double tolerance) const {
    return !touched_by_prediction() && !gap_of_prediction && unpredicted <= tolerance &&
           (unpredicted > 0 || closed_by_gap);
  }
};

/// Does the rule leave out the frontier whose region this is?
[[nodiscard]] inline bool left_out(const RegionArea& region, const SkipRule& rule) {
  return region.covered(rule.region_tolerance) || (rule.skip_wall_slivers && region.wall_sliver(rule.region_tolerance));
}

}  // namespace lookahead::exploration
