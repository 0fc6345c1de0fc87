#include "estimation/capped_weights.h"

#include <algorithm>
#include <vector>

namespace corridor {
namespace {

// `weights` capped at max_ratio times their median and scaled to a mean of 1, into *out.
void CapSide(const std::vector<double>& weights, double max_ratio, std::vector<double>* out) {
  out->assign(weights.begin(), weights.end());
  if (out->empty()) return;
  // The median's working copy, in the thread's buffer (it keeps its memory from solve to solve).
  thread_local std::vector<double> sorted;
  sorted.assign(weights.begin(), weights.end());
  const size_t mid = sorted.size() / 2;
  std::nth_element(sorted.begin(), sorted.begin() + mid, sorted.end());
  const double cap = max_ratio * sorted[mid];
  double sum = 0;
  for (double& w : *out) {
    w = std::min(w, cap);
    sum += w;
  }
  if (!(sum > 0)) return;
  const double scale = static_cast<double>(out->size()) / sum;
  for (double& w : *out) w *= scale;
}

}  // namespace

bool CapWeights(const CorridorObservation& observation, double max_ratio,
                CorridorObservation* capped) {
  if (!(max_ratio > 0) ||
      (observation.left_weights.empty() && observation.right_weights.empty())) {
    return false;
  }
  capped->fx = observation.fx;
  capped->fy = observation.fy;
  capped->cx = observation.cx;
  capped->cy = observation.cy;
  capped->camera_height = observation.camera_height;
  capped->left.assign(observation.left.begin(), observation.left.end());
  capped->right.assign(observation.right.begin(), observation.right.end());
  CapSide(observation.left_weights, max_ratio, &capped->left_weights);
  CapSide(observation.right_weights, max_ratio, &capped->right_weights);
  return true;
}

}  // namespace corridor
