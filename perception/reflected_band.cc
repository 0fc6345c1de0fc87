#include "perception/reflected_band.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "perception/band_profile.h"

namespace corridor {
namespace {

constexpr double kStepDeg = 0.1;       // The candidate lines' spacing about the vanishing point.
constexpr int kFloorSteps = 8;         // Candidates looked at beyond the junction, on the floor.
constexpr int kSamples = 48;           // Points along the nearer part of the junction's extent.
constexpr double kNearPart = 0.65;     // That part: near the vanishing point the band is a pixel.
constexpr int kMinBandSteps = 8;       // The thinnest band (baseboard and reflection) looked at.
constexpr double kMaxSlopeDeg = 80.0;  // Steeper lines: their slopes are not measured finely.
constexpr double kMinContrast = 30.0;  // Least wall/baseboard difference, summed over channels.
// The floor's gloss, the reflection's step over the baseboard's, in this range, to within this
// fraction of the baseboard's step; and the reflection unlike the baseboard by this fraction of it.
constexpr double kMinGloss = 0.15, kMaxGloss = 0.85, kMaxGlossResidual = 0.25, kMinUnlike = 0.05;
constexpr double kMinUnlikeLevels = 9.0;  // And by at least this, summed over channels.
// How far about the middle in slope (candidates) the step from baseboard to reflection is sought.
constexpr double kMaxMiddleOffset = 3.0;

}  // namespace

bool FindReflectedJunction(const cv::Mat& image, const JunctionLine& junction,
                           const Eigen::Vector2d& vanishing_point, bool left, double max_turn_deg,
                           double* turn_deg) {
  if (image.empty() || image.type() != CV_8UC3 || !vanishing_point.allFinite() ||
      !(max_turn_deg > 1) || max_turn_deg > 30) {
    return false;
  }
  const Eigen::Vector2d& vp = vanishing_point;
  Eigen::Vector2d down = junction.near_end - vp;
  const double r_near = down.norm();
  if (!(r_near > 1)) return false;
  down /= r_near;
  const double r_far = std::max(0.0, (junction.far_end - vp).dot(down));
  if (!(r_near > r_far + 8)) return false;
  const double step = kStepDeg * M_PI / 180.0;
  const int wall_steps = static_cast<int>(max_turn_deg / kStepDeg);
  const auto direction = [&](int k) { return TurnedDown(down, left, k * step); };
  // Radii whose points stay inside the image from the farthest candidate on the wall to the
  // farthest on the floor.
  const Eigen::Vector2d wall_end = direction(-wall_steps), floor_end = direction(kFloorSteps);
  const double r_start = std::max(r_far, r_near - kNearPart * (r_near - r_far));
  thread_local std::vector<double> radii;
  radii.clear();
  for (int i = 0; i < kSamples; ++i) {
    const double r = r_start + (r_near - r_start) * (i + 0.5) / kSamples;
    if (InsideRoi(image, 0, vp + r * wall_end) && InsideRoi(image, 0, vp + r * floor_end)) {
      radii.push_back(r);
    }
  }
  if (radii.size() < 8) return false;
  // The mean colour along each candidate, from the farthest on the wall (index 0) to the
  // farthest on the floor; index wall_steps is the junction.
  thread_local std::vector<cv::Vec3d> profile;
  profile.assign(static_cast<size_t>(wall_steps + kFloorSteps + 1), cv::Vec3d(0, 0, 0));
  for (int k = -wall_steps; k <= kFloorSteps; ++k) {
    profile[static_cast<size_t>(k + wall_steps)] =
        MeanColourAlong(image, 0, vp, direction(k), radii);
  }
  const auto at = [&](int k) { return profile[static_cast<size_t>(k + wall_steps)]; };
  const auto mean = [&](int from, int to) {
    cv::Vec3d sum(0, 0, 0);
    for (int k = from; k <= to; ++k) sum += at(k);
    return sum / static_cast<double>(to - from + 1);
  };
  const auto l1 = [](const cv::Vec3d& c) { return std::abs(c[0]) + std::abs(c[1]) + std::abs(c[2]); };
  // The change at candidate k: the two beyond it toward the wall against the two toward the floor.
  const auto change_at = [&](int k) { return l1((at(k - 1) + at(k - 2)) - (at(k + 1) + at(k + 2))); };
  // The band's top: the largest change toward the wall.
  int top = 0;
  double top_step = 0;
  for (int k = -wall_steps + 2; k <= -kMinBandSteps; ++k) {
    if (change_at(k) > top_step) top_step = change_at(k), top = k;
  }
  if (top == 0) return false;
  // The middle in slope below the horizontal through the vanishing point.
  const double below = std::atan2(down.y(), std::abs(down.x()));
  const double below_top = below + top * step;
  const double max_slope = kMaxSlopeDeg * M_PI / 180.0;
  if (!(below_top > 0) || !(below < max_slope)) return false;
  const double middle_angle = std::atan(0.5 * (std::tan(below) + std::tan(below_top)));
  const double middle = (middle_angle - below) / step;  // Candidates, negative.
  const int m = static_cast<int>(std::lround(middle));
  if (m - 2 < top + 2 || m + 2 > -2) return false;
  // Wall, baseboard, reflection, floor. The floor beside the reflection mirrors the wall above the
  // baseboard, so the step from the floor to the reflection is the step from the wall to the
  // baseboard, scaled by the floor's gloss; and the reflection, a blend of the floor and the
  // baseboard, is unlike the baseboard itself (a baseboard above a true junction is alike).
  const cv::Vec3d wall = mean(std::max(-wall_steps, top - 6), top - 2);
  const cv::Vec3d board = mean(top + 2, m - 2), mirror = mean(m + 2, -2);
  const cv::Vec3d floor = mean(2, kFloorSteps);
  const cv::Vec3d span = board - wall;
  const double contrast = l1(span);
  if (contrast < kMinContrast) return false;
  const double gloss = (mirror - floor).dot(span) / span.dot(span);
  if (gloss < kMinGloss || gloss > kMaxGloss) return false;
  const double unlike = l1(mirror - board);
  if (l1(mirror - floor - gloss * span) > kMaxGlossResidual * contrast ||
      unlike < std::max(kMinUnlikeLevels, kMinUnlike * contrast)) {
    return false;
  }
  // The baseboard meets its reflection where the mirror puts the junction: at the middle, the
  // band changes by most of the change from baseboard to reflection. (change_at sums two
  // candidates on each side: twice the step between two flat bands, so at least half of it.)
  // Elsewhere in the band a door's or a joint's reflection may change it as much: only the
  // middle is asked for a step.
  double middle_change = 0;
  const int lo = std::max(top + 5, static_cast<int>(std::floor(middle - kMaxMiddleOffset)));
  const int hi = std::min(-5, static_cast<int>(std::ceil(middle + kMaxMiddleOffset)));
  for (int k = lo; k <= hi; ++k) middle_change = std::max(middle_change, change_at(k));
  if (middle_change < unlike) return false;
  *turn_deg = middle * kStepDeg;
  return true;
}

}  // namespace corridor
