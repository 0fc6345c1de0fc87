#include "pipeline/far_wall_check.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "perception/ceiling_detector.h"

namespace corridor {

InnerLineCheck CheckFarWall(const cv::Mat& bgr, const Camera& camera,
                            const CeilingDetectorOptions& ceiling,
                            const InnerLineCheckOptions& options, const CeilingEstimate& found,
                            CorridorGeometry* geometry, ImageEdges* edges) {
  InnerLineCheck check;
  if (!(options.far_max_height > ceiling.max_height) || !found.found) return check;
  const double h = geometry->camera_height;
  const double distance[2] = {geometry->LeftDistance(), geometry->RightDistance()};
  for (int far = 0; far < 2; ++far) {
    // The trusted side's ceiling junction plainly seen, at a ceiling's height.
    const int trusted = 1 - far;
    const double height = found.side_height[trusted];
    if (found.side_visible_support[trusted] < options.min_far_ceiling_support ||
        height < ceiling.min_height || height > ceiling.max_height || !(height - h > 0.1)) {
      continue;
    }
    // The far wall moved in by r puts its ceiling junction, at the trusted height, where the
    // junction searched alone at its distance would be at h + r (height - h): r from where that
    // is above the ceiling search's max_height (below it, the search has seen the line) up to
    // far_max_height.
    const double sign = far == 0 ? -1.0 : 1.0;
    const double min_ratio =
        std::max(1 + options.min_disagreement, (ceiling.max_height - h) / (height - h));
    const double max_ratio = (options.far_max_height - h) / (height - h);
    std::vector<double> ratios, xs;
    for (double r = min_ratio; r <= max_ratio; r *= 1.01) {
      ratios.push_back(r);
      xs.push_back(sign * distance[far] / r);
    }
    const std::vector<double> supports =
        CorridorLinesSupport(bgr, camera, *geometry, xs, h - height, ceiling, edges);
    double best = 0, ratio = 0;
    for (size_t k = 0; k < supports.size(); ++k) {
      if (supports[k] > best) best = supports[k], ratio = ratios[k];
    }
    if (best < options.min_far_ceiling_support || best <= found.side_visible_support[far]) {
      continue;
    }
    const double moved = distance[far] / ratio;
    const double target =
        BestFloorLineSupportNear(bgr, camera, *geometry, sign * moved, 1.08, ceiling, edges);
    if (target < options.min_far_target_support) continue;
    check.target_support = target;
    check.side_height[trusted] = height;
    check.side_height[far] = h + ratio * (height - h);
    check.side_support[trusted] = found.side_visible_support[trusted];
    check.side_support[far] = best;
    geometry->SetWallDistances(far == 0 ? moved : distance[0], far == 1 ? moved : distance[1]);
    check.moved = true;
    check.far = true;
    check.side = far;
    check.factor = 1 / ratio;
    return check;
  }
  return check;
}

}  // namespace corridor
