#pragma once

// Private to the junction detector: when only one side has junction candidates, the one visible
// junction and where the corridor's other lines meet it.

#include <vector>

#include <Eigen/Core>

#include "corridor_depth/junction_lines.h"
#include "perception/junction_selector.h"
#include "perception/line_segments.h"

namespace corridor {

// The index in `side` of the outermost line (where it meets the bottom row, `height`: leftmost
// for the left side, else rightmost) among those that look like the floor's edge (boundary score
// at least 0.3 and half the side's best): grout lines and reflections lie inside the floor,
// baseboard tops and door bottoms have no floor below. -1 when no line qualifies.
int OutermostFloorEdge(const std::vector<JunctionCandidate>& side, bool is_left, int height);

// The vanishing point on `single` (the refined junction of the candidate line `chosen`) voted by
// `lines` at least `shortest` px long that cross it above its support's far end and are not
// within 5 degrees of parallel to it: the length-weighted median crossing, kept when at least 2
// votes, and at least half of them, lie within 3% of `height` of it along the line. False, with
// *vp and *votes untouched, otherwise.
bool VoteSingleVanishingPoint(const JunctionLine& single, const MergedLine& chosen,
                              const std::vector<MergedLine>& lines, double shortest, int height,
                              Eigen::Vector2d* vp, int* votes);

}  // namespace corridor
