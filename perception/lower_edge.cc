#include "perception/lower_edge.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "perception/band_profile.h"

namespace corridor {
namespace {

constexpr double kAngleStepDeg = 0.1;  // The candidate lines' spacing, degrees about the vanishing point.
constexpr int kSamples = 48;           // Points along the chosen line's extent.
constexpr double kMinBandPx = 4.0;     // The thinnest band looked at, px at the near end.
// Only the nearer part of the extent is sampled: near the vanishing point the band is under a
// pixel and the chosen line's own edge blurs across every candidate.
constexpr double kNearPart = 0.65;
// A profile colour nearer the band's than this fraction of the band's edge step is the band's.
constexpr double kReappears = 0.3;
// Over this many candidates in a row: a thin line beyond (a grout joint along the wall) darker or
// lighter than the band passes through the band's colour on its way, which is not the band.
constexpr int kReappearsOver = 5;
// The largest fraction of points whose band middle looks like the floor beyond the band: a
// baseboard is the band at most points.
constexpr double kMaxFloorLikeBand = 0.5;
// A band is flat between its two edges: the colour's change across the band falls below this
// fraction of the foot's. A blurred edge's tail or a reflection fading into the floor changes
// all the way and has no flat part, so no foot.
constexpr double kMaxValleyStep = 0.5;

}  // namespace

bool FindLowerEdge(const cv::Mat& roi, int roi_top, const MergedLine& chosen,
                   const Eigen::Vector2d& vanishing_point, bool left, double max_angle_deg,
                   MergedLine* lower, double* turn_deg) {
  if (roi.empty() || roi.type() != CV_8UC3 || !(max_angle_deg > 0) || max_angle_deg > 45 ||
      !vanishing_point.allFinite()) {
    return false;
  }
  const Eigen::Vector2d& vp = vanishing_point;
  Eigen::Vector2d down = LowEnd(chosen) - vp;
  const double reach = down.norm();
  if (!(reach > 1)) return false;
  down /= reach;
  const double ra = (chosen.start - vp).dot(down), rb = (chosen.end - vp).dot(down);
  const double r_far = std::max(0.0, std::min(ra, rb)), r_near = std::max(ra, rb);
  if (!(r_near > r_far + 1)) return false;
  const double deg = M_PI / 180.0;
  const double min_angle =
      std::max(3 * kAngleStepDeg, std::asin(std::min(1.0, kMinBandPx / r_near)) / deg);
  const int first = static_cast<int>(std::ceil(min_angle / kAngleStepDeg));
  const int last = static_cast<int>(max_angle_deg / kAngleStepDeg);
  if (first < 2 || first + 2 > last - 2) return false;
  // The sample distances from the vanishing point whose points stay inside the image from the
  // chosen line to the farthest candidate.
  const Eigen::Vector2d far_turn = TurnedDown(down, left, last * kAngleStepDeg * deg);
  const double r_start = std::max(r_far, r_near - kNearPart * (r_near - r_far));
  thread_local std::vector<double> radii;
  radii.clear();
  for (int i = 0; i < kSamples; ++i) {
    const double r = r_start + (r_near - r_start) * (i + 0.5) / kSamples;
    if (InsideRoi(roi, roi_top, vp + r * down) && InsideRoi(roi, roi_top, vp + r * far_turn)) {
      radii.push_back(r);
    }
  }
  if (radii.size() < 8) return false;
  // The mean colour along each candidate line, nearest the chosen line first, on beyond the
  // search as far again (the floor beyond an edge near the search's end).
  const int view_last = std::min(2 * last, static_cast<int>(45.0 / kAngleStepDeg));
  thread_local std::vector<cv::Vec3d> profile;
  profile.assign(static_cast<size_t>(view_last) + 1, cv::Vec3d(0, 0, 0));
  // The colour at distance r from the vanishing point along d.
  const auto colour_at = [&](const Eigen::Vector2d& d, double r) {
    return ColourAt(roi, roi_top, vp + r * d);
  };
  const auto direction = [&](double k) {
    const double a = k * kAngleStepDeg * deg;
    return TurnedDown(down, left, a);
  };
  for (int k = 0; k <= view_last; ++k) {
    profile[static_cast<size_t>(k)] = MeanColourAlong(roi, roi_top, vp, direction(k), radii);
  }
  // The step at each candidate: the two candidates beyond against the two before.
  const auto step_at = [&](int k) {
    const cv::Vec3d step = (profile[k + 1] + profile[k + 2]) - (profile[k - 1] + profile[k - 2]);
    return std::abs(step[0]) + std::abs(step[1]) + std::abs(step[2]);
  };
  int best = -1;
  double best_step = 0;
  for (int k = first; k <= last - 2; ++k) {
    const double size = step_at(k);
    if (size > best_step) best_step = size, best = k;
  }
  if (best < 0 || !(best_step > 0)) return false;
  double valley = best_step;
  for (int k = first; k <= best - 2; ++k) valley = std::min(valley, step_at(k));
  if (valley > kMaxValleyStep * best_step) return false;
  // A baseboard's colour is not seen again on the floor beyond its foot; a strip of floor between
  // the wall and a stripe is, beyond the stripe.
  cv::Vec3d band(0, 0, 0), beyond(0, 0, 0);
  const int band_end = std::max(first, best - 2);
  for (int k = first; k <= band_end; ++k) band += profile[k];
  band /= static_cast<double>(band_end - first + 1);
  for (int k = best + 3; k <= best + 5; ++k) beyond += profile[std::min(k, view_last)];
  beyond /= 3.0;
  const double edge = cv::norm(beyond - band, cv::NORM_L1);
  int run = 0;
  for (int k = best + 6; k <= view_last; ++k) {
    run = cv::norm(profile[k] - band, cv::NORM_L1) < kReappears * edge ? run + 1 : 0;
    if (run >= kReappearsOver) return false;
  }
  // A baseboard runs all along the wall: the band's middle looks like the band, not like the floor
  // beyond it, at most points; boxes or door bottoms standing across the junction darken the
  // floor at some points only.
  const double mid = 0.5 * (first + best);
  const Eigen::Vector2d middle[3] = {direction(mid - 1), direction(mid), direction(mid + 1)};
  int floor_like = 0;
  for (const double r : radii) {
    const cv::Vec3d c = (colour_at(middle[0], r) + colour_at(middle[1], r) +
                         colour_at(middle[2], r)) /
                        3.0;
    floor_like += cv::norm(c - beyond, cv::NORM_L1) < cv::norm(c - band, cv::NORM_L1);
  }
  if (floor_like > kMaxFloorLikeBand * static_cast<double>(radii.size())) return false;
  // The edge between candidates: the peak of a parabola through the steps around the largest.
  double peak = best;
  if (best - 1 >= 2 && best + 1 <= view_last - 2) {
    const double s0 = step_at(best - 1), s1 = best_step, s2 = step_at(best + 1);
    const double curvature = s0 - 2 * s1 + s2;
    if (curvature < 0) peak += std::clamp(0.5 * (s0 - s2) / curvature, -0.5, 0.5);
  }
  const double a = peak * kAngleStepDeg * deg;
  const Eigen::Vector2d d = TurnedDown(down, left, a);
  *lower = LineThrough(vp + r_far * d, vp + r_near * d);
  *turn_deg = peak * kAngleStepDeg;
  return true;
}

Eigen::Vector3d TurnTowardFloor(const Eigen::Vector3d& line, const Eigen::Vector2d& near_point,
                                const Eigen::Vector2d& vanishing_point, bool left,
                                double turn_deg) {
  // The line's direction from the vanishing point toward the near point.
  Eigen::Vector2d down(line.y(), -line.x());
  if (down.dot(near_point - vanishing_point) < 0) down = -down;
  return LineThrough(vanishing_point,
                     vanishing_point + TurnedDown(down, left, turn_deg * M_PI / 180.0))
      .line;
}

void TurnJunctionToFoot(const MergedLine& foot, double turn_deg,
                        const Eigen::Vector2d& vanishing_point, bool left, JunctionLine* line) {
  MergedLine turned;
  turned.line = TurnTowardFloor(line->line, line->near_end, vanishing_point, left, turn_deg);
  const Eigen::Vector2d ends[2] = {foot.start, foot.end};
  SetExtentAlongLine(ends, 2, &turned);
  const Eigen::Vector2d a = turned.start, b = turned.end;
  line->line = turned.line;
  line->near_end = a.y() > b.y() ? a : b;
  line->far_end = a.y() > b.y() ? b : a;
  const double length = (b - a).norm();
  line->support.clear();
  for (double t = 0; length > 0 && t <= length; t += 1) {
    line->support.push_back(a + (b - a) * (t / length));
  }
}

}  // namespace corridor
