#pragma once

#include <memory>
#include <mutex>

#include "depth/ray_table.h"
#include "corridor_depth/rasterizer.h"

namespace corridor {

// docs/geometry.md, sections 3 and 6: for every pixel, the smallest valid depth among floor, walls
// and (when known) ceiling. Along a row every dot product is affine in u; a ray table, built
// once per camera, handles distortion.
class ExactRasterizer : public DepthRasterizer {
 public:
  explicit ExactRasterizer(const RasterizerOptions& options) : options_(options) {}
  std::string Name() const override { return "exact"; }
  Status Render(const CorridorGeometry& geometry, const Camera& camera,
                cv::Mat* depth) const override;
  // NaN written where Render writes 0, in the same pass.
  Status RenderNoEstimateNaN(const CorridorGeometry& geometry, const Camera& camera,
                             cv::Mat* depth) const override;

 private:
  // Render with `none` (0 or NaN) where there is no estimate.
  Status RenderWith(const CorridorGeometry& geometry, const Camera& camera, float none,
                    cv::Mat* depth) const;
  std::shared_ptr<const RayTable> TableFor(const Camera& camera) const;

  const RasterizerOptions options_;
  mutable std::mutex table_mutex_;
  mutable std::shared_ptr<const RayTable> table_;  // Cached for the last distorted camera.
};

}  // namespace corridor
