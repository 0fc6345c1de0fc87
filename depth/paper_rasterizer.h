#pragma once

#include "corridor_depth/rasterizer.h"

namespace corridor {

// The paper's depth planes (III-C.3, eqs. 18-22), as fixed in docs/geometry.md section 6. Plane
// Gamma_k is the cross-section Z_W = z_k through the k-th pair of junction points: in the image a
// polyline (left wall segment, floor segment, right wall segment). A pixel takes the two planes
// that bracket it and interpolates their depths: between the planes linearly in v on the floor
// and in u on a wall; along a plane's segment linearly between its vertices' real camera depths
// (the paper used the virtual camera's depth, which ignores yaw; docs/geometry.md corrects that).
// The paper drops the ceiling: pixels above the maximum height (or the ceiling junction, when it
// is known) get 0, as do pixels beyond the farthest plane (max_range). Lens distortion is
// ignored, as in the paper.
class PaperRasterizer : public DepthRasterizer {
 public:
  explicit PaperRasterizer(const RasterizerOptions& options) : options_(options) {}
  std::string Name() const override { return "paper"; }
  Status Render(const CorridorGeometry& geometry, const Camera& camera,
                cv::Mat* depth) const override;

 private:
  const RasterizerOptions options_;
};

}  // namespace corridor
