#include "estimation/line_fit.h"

#include <cmath>

#include "estimation/junction_line_residual.h"

namespace corridor {

bool JunctionLineRms(const CorridorGeometry& geometry, const CorridorObservation& observation,
                     double* rms) {
  const FloorIntrinsics k{observation.fx, observation.fy, observation.cx, observation.cy,
                          observation.camera_height};
  const double x[JunctionLineResidual::kNumParameters] = {geometry.yaw, geometry.pitch,
                                                          geometry.offset, geometry.width};
  double sum = 0, n = 0;
  bool defined = true;
  for (const int side : {-1, 1}) {
    const std::vector<Eigen::Vector2d>& points = side < 0 ? observation.left : observation.right;
    for (size_t i = 0; i < points.size(); ++i) {
      double r = 0;
      defined = defined && JunctionLineResidual(k, points[i].x(), points[i].y(), side)(x, &r) &&
                std::isfinite(r);
      const double w = observation.Weight(side, i);
      sum += w * r * r;
      n += w;
    }
  }
  *rms = n > 0 ? std::sqrt(sum / n) : 0.0;
  return defined;
}

}  // namespace corridor
