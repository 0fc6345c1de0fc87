#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "corridor_depth/corridor_geometry.h"
#include "corridor_depth/junction_lines.h"
#include "perception/working_image.h"

namespace corridor {

// Whether the floor goes on across a chosen junction line. A wall's foot has the wall on one side
// all along its view, or an object standing before the wall; a box's, a bench's or a pillar's
// front foot ends where the object ends, and beyond it the floor goes on across the line up to
// the wall's own foot. Along the line, from its support's near end toward the vanishing point,
// each point compares the colours just across the line (the wall side against the floor side)
// and both against the floor's middle at the same image row (the same depth): the floor is on
// both sides where the contrast across is far below the line's own and both sides look like that
// floor, and the line has no edge support of its own there.
struct FloorBeyond {
  int samples = 0;          // Points of the line measured (0: nothing measured).
  double contrast = 0;      // The line's own contrast across it (the upper quartile, colour sum).
  double floor_across = 0;  // Fraction of the points with the floor on both sides, in runs
                            // longer along the corridor than a doorway.
};

// `line`: the junction (raw pixels of the full image, with its support pixels); `other`: the other
// side's junction, whose support's far end bounds how far the corridor's floor is known to go on;
// `vp`: the two lines' vanishing point. `search` is the frame at the search resolution with its
// camera; `geometry` gives the floor plane (pitch, yaw, camera height) that puts a point of the
// line at its distance along the corridor, and the end wall's distance (when seen), beyond which
// nothing is examined. Distortion is ignored for the few pixels measured
// across the line.
FloorBeyond MeasureFloorBeyond(const WorkingImage& search, const CorridorGeometry& geometry,
                               const JunctionLine& line, const JunctionLine& other,
                               const Eigen::Vector2d& vp);

}  // namespace corridor
