#pragma once

#include <string>

namespace corridor {

// The straight-corridor model of docs/geometry.md, section 2. Radians and metres.
struct CorridorGeometry {
  double yaw = 0.0;             // phi: > 0 when the corridor axis appears right of cx.
  double pitch = 0.0;           // theta: > 0 when the camera is pitched down.
  double offset = 0.0;          // tau = (d_l - d_r) / 2: > 0 when the camera is right of centre.
  double width = 0.0;           // w = d_l + d_r.
  double camera_height = 0.0;   // h: optical centre above the floor.
  double ceiling_height = 0.0;  // H_c above the floor; 0 = unknown.
  double end_distance = 0.0;    // Z_W of an end wall across the corridor (beyond the paper); 0 = none seen.

  double LeftDistance() const { return 0.5 * width + offset; }   // d_l
  double RightDistance() const { return 0.5 * width - offset; }  // d_r
  // Sets width and offset from the distances to the walls: w = d_l + d_r, tau = (d_l - d_r) / 2.
  void SetWallDistances(double left, double right) {
    width = left + right;
    offset = 0.5 * (left - right);
  }
  bool HasCeiling() const { return ceiling_height > camera_height; }
  bool HasEndWall() const { return end_distance > 0; }
  std::string ToString() const;
};

}  // namespace corridor
