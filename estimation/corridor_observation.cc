#include "corridor_depth/corridor_observation.h"

#include <cmath>

namespace corridor {
namespace {

bool AllFinite(const std::vector<Eigen::Vector2d>& points) {
  for (const auto& p : points) {
    if (!p.allFinite()) return false;
  }
  return true;
}

// Empty, or one finite weight >= 0 per point with at least two positive.
bool WeightsValid(const std::vector<double>& weights, size_t points) {
  if (weights.empty()) return true;
  if (weights.size() != points) return false;
  int positive = 0;
  for (const double w : weights) {
    if (!(w >= 0 && std::isfinite(w))) return false;
    positive += w > 0 ? 1 : 0;
  }
  return positive >= 2;
}

}  // namespace

CorridorObservation CorridorObservation::FromCamera(const Camera& camera) {
  CorridorObservation obs;
  obs.fx = camera.fx;
  obs.fy = camera.fy;
  obs.cx = camera.cx;
  obs.cy = camera.cy;
  obs.camera_height = camera.mount_height;
  return obs;
}

bool CorridorObservation::Check(std::string* why) const {
  std::string reason;
  if (!(fx > 0 && fy > 0 && std::isfinite(fx) && std::isfinite(fy) && std::isfinite(cx) &&
        std::isfinite(cy))) {
    reason = "intrinsics must be finite with positive focal lengths";
  } else if (!(camera_height > 0 && std::isfinite(camera_height))) {
    reason = "camera height must be positive";
  } else if (left.size() < 2 || right.size() < 2) {
    reason = "each junction needs at least 2 points (left " + std::to_string(left.size()) +
             ", right " + std::to_string(right.size()) + ")";
  } else if (!AllFinite(left) || !AllFinite(right)) {
    reason = "junction points must be finite";
  } else if (!WeightsValid(left_weights, left.size()) ||
             !WeightsValid(right_weights, right.size())) {
    reason =
        "junction weights must be empty or one per point, finite and >= 0, with at least 2 "
        "positive a side";
  }
  if (reason.empty()) return true;
  if (why != nullptr) *why = reason;
  return false;
}

}  // namespace corridor
