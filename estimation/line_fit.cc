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
  double sum = 0;
  int n = 0;
  bool defined = true;
  for (const int side : {-1, 1}) {
    for (const Eigen::Vector2d& p : side < 0 ? observation.left : observation.right) {
      double r = 0;
      defined = defined && JunctionLineResidual(k, p.x(), p.y(), side)(x, &r) && std::isfinite(r);
      sum += r * r;
      ++n;
    }
  }
  *rms = n > 0 ? std::sqrt(sum / n) : 0.0;
  return defined;
}

}  // namespace corridor
