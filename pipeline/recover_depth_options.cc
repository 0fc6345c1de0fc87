#include "corridor_depth/recover_depth.h"

#include <cmath>
#include <string>

namespace corridor {

bool RecoverDepthOptions::Check(std::string* why) const {
  std::string reason;
  if (points_per_line < 3 || points_per_line > 10000) {
    reason = "points_per_line must be in [3, 10000]";
  } else if (solver_evidence != "lines" && solver_evidence != "edges") {
    reason = "solver_evidence must be lines or edges, not '" + solver_evidence + "'";
  } else if (!(min_width > 0 && min_width < max_width && std::isfinite(max_width))) {
    reason = "width bounds must satisfy 0 < min_corridor_width < max_corridor_width";
  } else if (!(max_abs_yaw > 0 && max_abs_yaw < M_PI / 2)) {
    reason = "max_abs_yaw must be in (0, pi/2)";
  } else if (!(max_abs_pitch > 0 && max_abs_pitch < M_PI / 2)) {
    reason = "max_abs_pitch must be in (0, pi/2)";
  } else if (!(max_line_error > 0 && std::isfinite(max_line_error))) {
    reason = "max_line_error must be positive and finite";
  } else if (!(width_prior >= 0 && std::isfinite(width_prior))) {
    reason = "width_prior must be >= 0 (0 = none)";
  } else if (!(max_width_change >= 0 && max_width_change < 1)) {
    reason = "max_width_change must be in [0, 1) (0 = off)";
  } else if (!(max_ceiling_disagreement >= 0 && std::isfinite(max_ceiling_disagreement))) {
    reason = "max_ceiling_disagreement must be finite and >= 0 (0 = off)";
  } else if (!(max_ceiling_change >= 0 && max_ceiling_change < 1)) {
    reason = "max_ceiling_change must be in [0, 1) (0 = off)";
  } else if (!(ceiling_height >= 0 && std::isfinite(ceiling_height))) {
    reason = "ceiling_height must be >= 0 (0 = unknown)";
  } else if (!(min_confidence >= 0 && min_confidence <= 1)) {
    reason = "min_confidence must be in [0, 1] (0 = never refuse on confidence)";
  } else if (search_max_width != 0 && search_max_width < 64) {
    reason = "search_max_width must be 0 (full resolution) or at least 64 px";
  } else if (!perception.Check(&reason)) {
    reason = "perception: " + reason;
  } else if (!tracker.Check(&reason)) {
    reason = "tracker: " + reason;
  } else if (!ceiling.Check(&reason)) {
    reason = "ceiling: " + reason;
  } else if (!end_wall.Check(&reason)) {
    reason = "end_wall: " + reason;
  } else if (!inner_line.Check(&reason)) {
    reason = "inner_line: " + reason;
  } else if (!baseboard_feet.Check(&reason)) {
    reason = "baseboard_feet: " + reason;
  } else if (!vertical_crossings.Check(&reason)) {
    reason = "vertical_crossings: " + reason;
  } else if (!ceiling_split.Check(&reason)) {
    reason = "ceiling_split: " + reason;
  }
  if (reason.empty()) return true;
  if (why != nullptr) *why = reason;
  return false;
}

}  // namespace corridor
