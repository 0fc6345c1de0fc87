#pragma once

#include <opencv2/core.hpp>

#include "corridor_depth/junction_lines.h"

namespace corridor {

// The wall's own junction behind a row of objects. When the floor goes on across a chosen junction
// (floor_beyond_junction.h), the line taken is an object's front foot (a pillar's, a bench's, a
// locker's), and the wall's foot lies further out, seen between the objects. It is a floor/wall
// junction like the chosen one: a line through the same vanishing point, on the wall's side of the
// chosen line, made of the image's segments that point at that vanishing point.
//
// From `junctions` (both lines ok, with their segments, raw pixels) and side 0 (left) or 1
// (right): the segments wholly on the wall's side of that side's line, below the vanishing point,
// whose direction points at it (within kMaxAim) are grouped by their angle about it; the group
// nearest the chosen line (at least kMinTurn outward, at most kMaxTurn) whose segments are long
// enough together (kMinSupport of the image height) gives the line through the vanishing point,
// refitted on the image's colour edges along it (junction_refit.h) over the group's extent, and
// taken when its edge points have the floor below them (kMinFloorBelow; an object's top edge,
// which points at the vanishing point too, has the object's face below). Groups are tried
// nearest first. False, and *outer untouched, when none is taken.
// `bgr` is the frame (8-bit, 3 channels, raw pixels); `scale` the junction search's working
// scale for it (appearance.h's probes).
bool FindOuterJunction(const JunctionPair& junctions, int side, const cv::Mat& bgr, int scale,
                       JunctionLine* outer);

// Puts `line` in side s's place in *pair (0 left, 1 right), without that side's lower line (it was
// the old line's), and the vanishing point where the two lines now meet. False, and *pair
// untouched, when they are parallel.
bool ReplaceJunction(int side, JunctionLine line, JunctionPair* pair);

}  // namespace corridor
