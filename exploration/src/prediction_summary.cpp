// SPDX-License-Identifier: MIT
#include "lookahead/exploration/prediction_summary.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace lookahead::exploration {
namespace {

void summarize_records(const std::vector<PredictionRecord>& records, PredictionSummary& s) {
  std::size_t cells = 0, correct = 0;
  for (const PredictionRecord& r : records) {
    ++s.requests;
    s.no_control_point += r.status == "no_control_point";
    s.no_match += r.status == "no_match";
    s.mean_seconds += r.seconds / static_cast<double>(records.size());
    s.max_seconds = std::max(s.max_seconds, r.seconds);
    if (r.status != "predicted") continue;
    ++s.hypotheses;
    s.psi_world.push_back(r.truth.psi);
    s.psi_solid_world.push_back(r.truth.psi_solid_world);
    s.hypothesis_records.push_back(r);
    s.predicted_area += r.area;
    cells += r.truth.cells;
    correct += r.truth.correct;
  }
  for (const double psi : s.psi_world) {
    s.mean_psi_world += psi / static_cast<double>(s.psi_world.size());
    s.share_psi_world_above_04 += (psi > 0.4 ? 1.0 : 0.0) / static_cast<double>(s.psi_world.size());
  }
  s.cell_accuracy = cells ? static_cast<double>(correct) / static_cast<double>(cells) : 0.0;
}

// The look-ahead map where the robot's map is still unknown, against the world: all of it, and
// the part a robot could observe (as a target choice reads it, score_prediction_in_use).
void summarize_final_map(const Mission& m, const PredictedMap& pm, double occupied, PredictionSummary& s) {
  slam::CellIndex lo, hi;
  if (!pm.cells().known_bounds(lo, hi)) return;
  std::size_t cells = 0, correct = 0;
  for (int y = lo.y; y <= hi.y; ++y) {
    for (int x = lo.x; x <= hi.x; ++x) {
      if (!pm.predicted(m.map(), {x, y})) continue;
      double cx = 0, cy = 0;
      pm.cells().cell_center({x, y}, cx, cy);
      ++cells;
      correct += prediction_matches_world(pm.cells().probability({x, y}) >= occupied, m.world(), cx, cy);
    }
  }
  PredictionInUse inside;
  score_prediction_in_use(pm, m.map(), m.world(), observable_cells(m.world(), m.reachable()), occupied, inside);
  const double res = pm.cells().resolution();
  s.final_predicted_area = static_cast<double>(cells) * res * res;
  s.final_predicted_accuracy = cells ? static_cast<double>(correct) / static_cast<double>(cells) : 0.0;
  s.final_predicted_area_inside = static_cast<double>(inside.cells) * res * res;
  s.final_predicted_accuracy_inside =
      inside.cells ? static_cast<double>(inside.correct) / static_cast<double>(inside.cells) : 0.0;
  s.coverage_with_predictions = m.coverage_meter().coverage(m.observed_map(), [&](double x, double y) {
    const slam::CellIndex c = pm.cells().cell_at(x, y);
    return pm.predicted(m.map(), c) && pm.cells().probability(c) < occupied && !m.world().is_occupied(x, y);
  });
}

void summarize_skip_protocol(const Mission& m, PredictionSummary& s) {
  s.rest_predicted_time = m.statistics().rest_predicted_time;
  const std::vector<CoverageSample>& curve = m.coverage_curve();
  const auto goal = std::find_if(curve.begin(), curve.end(), [&](const CoverageSample& c) {
    return c.coverage_with_predictions >= m.options().coverage_goal;
  });
  if (goal != curve.end()) s.time_to_goal_with_predictions = goal->time;
  for (const double t : {s.rest_predicted_time, s.time_to_goal_with_predictions})
    if (t >= 0 && (s.skip_protocol_end < 0 || t < s.skip_protocol_end)) s.skip_protocol_end = t;
  if (s.skip_protocol_end < 0) return;
  const auto end =
      std::find_if(curve.begin(), curve.end(), [&](const CoverageSample& c) { return c.time >= s.skip_protocol_end; });
  if (end == curve.end()) return;
  s.coverage_with_predictions_at_skip_end = end->coverage_with_predictions;
  s.path_at_skip_end = end->path_length;
}

}  // namespace

PredictionSummary summarize_predictions(const Mission& m) {
  PredictionSummary s;
  s.coverage_with_predictions = m.coverage();
  const LookaheadMapping* la = m.lookahead();
  if (!la) return s;
  s.enabled = true;
  summarize_records(la->records(), s);
  s.in_use = la->in_use();
  summarize_final_map(m, la->predicted(), la->options().predictor.features.occupied_threshold, s);
  summarize_skip_protocol(m, s);
  if (const slam::Rbpf* f = m.slam()) {
    s.filter_hypotheses = f->statistics().hypotheses_added;
    s.filter_predicted_updates = f->statistics().predicted_updates;
    s.filter_used = f->statistics().prediction_used;
    s.filter_rejected = f->statistics().prediction_rejected;
  }
  return s;
}

}  // namespace lookahead::exploration
