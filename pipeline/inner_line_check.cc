#include "pipeline/inner_line_check.h"

#include <cmath>

namespace corridor {

bool InnerLineCheckOptions::Check(std::string* why) const {
  std::string reason;
  if (!(min_disagreement > 0 && std::isfinite(min_disagreement))) {
    reason = "min_disagreement must be positive";
  } else if (!(min_support > 0 && min_support <= 1) ||
             !(strong_support > 0 && strong_support <= 1)) {
    reason = "min_support and strong_support must be in (0, 1]";
  } else if (!(min_above_camera > 0 && std::isfinite(min_above_camera))) {
    reason = "min_above_camera must be positive";
  } else if (!(max_line_support > 0 && max_line_support <= 1)) {
    reason = "max_line_support must be in (0, 1]";
  }
  if (reason.empty()) return true;
  if (why != nullptr) *why = reason;
  return false;
}

InnerLineCheck CheckInnerLine(const cv::Mat& bgr, const Camera& camera,
                              const CeilingDetectorOptions& ceiling,
                              const InnerLineCheckOptions& options, CorridorGeometry* geometry,
                              ImageEdges* edges, std::array<bool, 2> has_lower) {
  InnerLineCheck check;
  const double h = geometry->camera_height;
  CeilingDetectorOptions wide = ceiling;
  // The side too near gives the lower ceiling, the other one at most max_height.
  wide.min_height = h + options.min_above_camera;
  if (!(wide.max_height > wide.min_height)) return check;
  CeilingEstimate sides;
  if (!DetectCeiling(bgr, camera, *geometry, wide, &sides, edges).ok()) return check;
  for (int s = 0; s < 2; ++s) {
    check.side_height[s] = sides.side_height[s];
    check.side_support[s] = sides.side_support[s];
  }
  // Each side's ceiling above the camera: proportional to its wall's distance.
  const double above[2] = {sides.side_height[0] - h, sides.side_height[1] - h};
  if (!(above[0] > 0) || !(above[1] > 0)) return check;
  const int inner = above[0] < above[1] ? 0 : 1;
  // Both sides on at least half their samples; or, where the trusted side's junction shows only
  // from a few metres on, that side on its samples in view and the side to move strong (a wall put
  // too near sees its ceiling junction, scaled down, over most of the samples).
  const bool both = sides.side_support[0] >= options.min_support &&
                    sides.side_support[1] >= options.min_support;
  const bool narrow_view = sides.side_visible_support[1 - inner] >= options.min_support &&
                           sides.side_support[inner] >= options.strong_support &&
                           !has_lower[1 - inner];
  if (!both && !narrow_view) return check;
  const double factor = above[1 - inner] / above[inner];
  const double trusted = sides.side_height[1 - inner];
  if (!(factor > 1 + options.min_disagreement) || trusted < ceiling.min_height ||
      trusted > ceiling.max_height) {
    return check;
  }
  // A box's edge or a floor line taken for the junction follows edges over part of the way; a line
  // on edges nearly all along, as a junction is, stays (the other wall is then the wrong one: put
  // too far, which this check cannot tell from this one put too near).
  const double wall_x = inner == 0 ? -geometry->LeftDistance() : geometry->RightDistance();
  check.line_support =
      CorridorLineSupport(bgr, camera, *geometry, wall_x, h, ceiling, edges);
  if (check.line_support >= options.max_line_support) return check;
  double distance[2] = {geometry->LeftDistance(), geometry->RightDistance()};
  distance[inner] *= factor;
  geometry->SetWallDistances(distance[0], distance[1]);
  check.moved = true;
  check.side = inner;
  check.factor = factor;
  return check;
}

}  // namespace corridor
