// SPDX-License-Identifier: MIT
// One picture per hypothesis of a mission (LookaheadOptions::pictures): the map the
// prediction was made on, the target and reference regions, the control points, the
// hypothesis, and the true walls of the target region in pale red (under it), so a low Psi against
// the world can be told apart: a wrong registration, or a right one scored over cells no robot
// sees.
#pragma once

#include <string>

#include "lookahead/exploration/lookahead_mapping.hpp"
#include "lookahead/exploration/world.hpp"

namespace lookahead::exploration {

/// Writes DIR/NNN.png and the map as DIR/NNN.pgm/.yaml for every snapshot kept by
/// `lookahead` (NNN: the hypothesis' index in run.json's prediction.hypothesis_list).
void write_hypothesis_pictures(const LookaheadMapping& lookahead, const World& world, const std::string& dir);

}  // namespace lookahead::exploration
