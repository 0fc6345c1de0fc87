#pragma once

#include <string>

#include <diagnostic_msgs/DiagnosticStatus.h>

#include "corridor_depth/camera.h"
#include "corridor_depth/recover_depth.h"

namespace corridor {

// corridor/geometry: one diagnostic_msgs/DiagnosticStatus per input frame, published whether the
// frame gave depth or not, so that a program can follow the corridor without parsing text:
//   level   OK (ok), WARN (refused: no corridor, implausible geometry, low confidence) or ERROR
//           (failed: bad image, bad camera_info, no camera height);
//   name    "corridor_depth/geometry"; message: "ok" or the reason; hardware_id: the frame_id;
//   values  key/value pairs, named as geometry.csv's columns (numbers as text, "nan" when unknown):
//           stamp (the image's, "<sec>.<nsec>"), status (ok/refused/failed), note (as in
//           geometry.csv: "<code>: <reason>", or how an ok geometry was completed), confidence
//           (RecoverDepthResult::confidence, in [0, 1]; nan when the frame never reached it),
//           yaw_rad, pitch_rad, roll_rad (the roll the frame was recovered level from, 0 when
//           none was found: the other values are the level camera's), offset_m, width_m,
//           ceiling_height_m (0 = unknown),
//           end_distance_m (0 = none seen), camera_height_m, fx_px, fy_px, cx_px, cy_px,
//           time_s (the library's processing time).
// `status` is the frame's outcome (result.status, or why it never reached the library).
diagnostic_msgs::DiagnosticStatus GeometryMessage(const std::string& stamp,
                                                  const std::string& frame_id,
                                                  const Status& status,
                                                  const RecoverDepthResult* result,
                                                  const Camera* camera);

}  // namespace corridor
