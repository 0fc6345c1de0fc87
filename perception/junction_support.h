#pragma once

// Private to the junction detector: a chosen line's final fit on the edge pixels near it.

#include <vector>

#include <Eigen/Core>

#include "corridor_depth/junction_lines.h"
#include "perception/junction_selector.h"

namespace corridor {

// The pixels of `side` within `distance` of `line` (a u + b v + c = 0, a^2 + b^2 = 1), in order.
void SupportPixels(const std::vector<Eigen::Vector2d>& side, const Eigen::Vector3d& line,
                   double distance, std::vector<Eigen::Vector2d>* support);

// The final JunctionLine of a candidate: refitted (FitLineLeastDistance, up to three rounds,
// the first within twice `distance`) on the edge pixels on its floor side of `vp`
// (FloorSidePixels) that lie within `distance` of it, and, where that fit bends between two edges a
// few pixels apart (a junction near the camera, a grout line or a baseboard's top beside it far
// off, or the other way round), refitted on the one of the two that runs the whole way; the
// extent of that support along the line, the number of whole pixels it covers, and a confidence
// from the boundary score and that length over a quarter of `image_height`. With fewer than 8 support pixels the extent is the
// candidate's own ends.
JunctionLine RefineJunction(const JunctionCandidate& candidate,
                            const std::vector<Eigen::Vector2d>& edges, const Eigen::Vector2d& vp,
                            bool left, double distance, double image_height);

}  // namespace corridor
