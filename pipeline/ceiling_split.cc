#include "pipeline/ceiling_split.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "perception/ceiling_detector.h"

namespace corridor {

bool CeilingSplitOptions::Check(std::string* why) const {
  std::string reason;
  if (!(min_visible_support > 0 && min_visible_support <= 1)) {
    reason = "min_visible_support must be in (0, 1]";
  } else if (!(max_joint_support >= 0 && max_joint_support <= 1)) {
    reason = "max_joint_support must be in [0, 1] (0 = never)";
  } else if (!(min_disagreement > 0 && std::isfinite(min_disagreement))) {
    reason = "min_disagreement must be positive";
  } else if (!(min_alternative_support > 0 && min_alternative_support <= 1)) {
    reason = "min_alternative_support must be in (0, 1]";
  }
  if (reason.empty()) return true;
  if (why != nullptr) *why = reason;
  return false;
}

double CeilingSplit(const cv::Mat& bgr, const Camera& camera, const CorridorGeometry& g,
                    const CeilingEstimate& ceiling, const CeilingDetectorOptions& ceiling_options,
                    const CeilingSplitOptions& options, ImageEdges* edges) {
  if (!ceiling.found) return -1;
  const double h = g.camera_height;
  const double above[2] = {ceiling.side_height[0] - h, ceiling.side_height[1] - h};
  if (!(above[0] > 0.1 && above[1] > 0.1)) return -1;
  // Each side plainly seen on its own, at heights apart, and no one height fits both.
  if (std::min(ceiling.side_visible_support[0], ceiling.side_visible_support[1]) <
          options.min_visible_support ||
      std::min(ceiling.left_support, ceiling.right_support) >= options.max_joint_support) {
    return -1;
  }
  const int far = above[0] > above[1] ? 0 : 1, near = 1 - far;
  const double factor = above[far] / above[near];
  if (!(factor > 1 + options.min_disagreement)) return -1;
  // The two layouts that would agree with the ceiling: the far wall in, or the near wall out.
  const double distance[2] = {-g.LeftDistance(), g.RightDistance()};
  const double in = BestFloorLineSupportNear(bgr, camera, g, distance[far] / factor, 1.08,
                                             ceiling_options, edges);
  if (in < options.min_alternative_support) {
    const double out = BestFloorLineSupportNear(bgr, camera, g, distance[near] * factor, 1.08,
                                                ceiling_options, edges);
    if (out < options.min_alternative_support) return -1;
  }
  return std::log(factor);
}

}  // namespace corridor
