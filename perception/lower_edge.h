#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "corridor_depth/junction_lines.h"
#include "perception/line_segments.h"

namespace corridor {

// A baseboard's top and bottom edges (the junction) meet the vanishing point within a few
// degrees of each other in the image: the farthest a foot is sought from the line above it.
constexpr double kBaseboardMaxTurnDeg = 6.0;

// Where the line search found no line for it, the lower edge of a band below `chosen` (a
// baseboard's foot, the floor/wall junction when `chosen` is the baseboard's top): the line
// through `vanishing_point`, turned from `chosen` toward the floor by up to `max_angle_deg`, across
// which the mean colour along the line changes most. Each candidate line's colour is the mean of
// the same points along the nearer part of `chosen`'s extent, so a carpet's or a tile's texture,
// which breaks the edge into pieces too short for the line search, averages out while the band's
// step does not. No edge when the band's colour is seen again beyond it (a strip of floor between
// the wall and a stripe is floor, and the floor goes on beyond the stripe).
// `roi` is the 8-bit BGR image's rows [roi_top, rows); `left`: the left wall's junction (the floor
// side is to its right). *turn_deg: the edge's turn from `chosen`. False when there is no edge,
// the band would be too thin to look at (under 4 px at the near end), or too few points of
// `chosen` are inside the image.
bool FindLowerEdge(const cv::Mat& roi, int roi_top, const MergedLine& chosen,
                   const Eigen::Vector2d& vanishing_point, bool left, double max_angle_deg,
                   MergedLine* lower, double* turn_deg);

// The line through `vanishing_point` turned from `line` (which must pass near it) toward the
// floor by `turn_deg` degrees: FindLowerEdge's edge about a refined vanishing point. `left` as
// there.
Eigen::Vector3d TurnTowardFloor(const Eigen::Vector3d& line, const Eigen::Vector2d& near_point,
                                const Eigen::Vector2d& vanishing_point, bool left,
                                double turn_deg);

// The junction of a band's lower edge found by FindLowerEdge, from *line, the junction above it
// (raw pixels): turned about `vanishing_point` by `turn_deg`, over the extent of `foot`; its
// support every pixel along that extent, where MeasureJunctionEdgePoints seeks the edge itself.
// Its support length and confidence stay the line's: the line search's evidence, which the band
// test moved.
void TurnJunctionToFoot(const MergedLine& foot, double turn_deg,
                        const Eigen::Vector2d& vanishing_point, bool left, JunctionLine* line);

}  // namespace corridor
