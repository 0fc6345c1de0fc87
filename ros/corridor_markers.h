#pragma once

#include <std_msgs/Header.h>
#include <visualization_msgs/MarkerArray.h>

#include "corridor_depth/corridor_geometry.h"

namespace corridor {

// corridor/markers: the recovered corridor box for RViz, in the camera's optical frame (the
// header's frame_id; x right, y down, z forward), namespace "corridor", one TRIANGLE_LIST marker
// per surface, ids:
//   0 floor (Y_W = h), 1 left wall (X_W = -d_l), 2 right wall (X_W = d_r),
//   3 ceiling (Y_W = h - H_c; when the ceiling is known), 4 end wall (Z_W = L; when one was seen).
// Each is a quad in the corridor frame W of geometry.md (origin at the optical centre, Y down,
// Z along the axis), from the camera's cross-section Z_W = 0 to the end wall, else to
// `max_range`; the walls reach the ceiling, else `max_height` above the floor. Its six points are
// the corners (c0, c1, c2, c0, c2, c3) mapped to the camera frame by
// P_C = R_z(roll) R_x(pitch) R_y(yaw) P_W, `roll` the frame's RecoverDepthResult::roll (a frame
// recovered level has its geometry in the level camera).
// A surface the geometry lacks is a DELETE of its id, so that RViz drops a stale one.
visualization_msgs::MarkerArray CorridorMarkers(const CorridorGeometry& geometry, double max_range,
                                                double max_height, const std_msgs::Header& header,
                                                double roll = 0);

// For a frame without a geometry: one DELETEALL marker.
visualization_msgs::MarkerArray ClearCorridorMarkers(const std_msgs::Header& header);

}  // namespace corridor
