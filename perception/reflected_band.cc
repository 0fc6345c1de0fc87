#include "perception/reflected_band.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "perception/band_profile.h"

namespace corridor {
namespace {

constexpr double kStepDeg = 0.1;       // The candidate lines' spacing about the vanishing point.
constexpr int kFloorSteps = 8;         // Candidates looked at beyond the band, on the floor.
constexpr int kSamples = 48;           // Points along the nearer part of the junction's extent.
constexpr double kNearPart = 0.65;     // That part: near the vanishing point the band is a pixel.
constexpr int kMinBandSteps = 8;       // The thinnest band (baseboard and reflection) looked at.
constexpr double kMaxSlopeDeg = 80.0;  // Steeper lines: their slopes are not measured finely.
constexpr double kMinContrast = 30.0;  // Least wall/baseboard difference, summed over channels.
// The floor's gloss, the reflection's step over the baseboard's, in this range, to within this
// fraction of the baseboard's step; and the reflection unlike the baseboard by this fraction of it.
constexpr double kMinGloss = 0.15, kMaxGloss = 0.85, kMinUnlike = 0.05;
constexpr double kMinUnlikeLevels = 9.0;  // And by at least this, summed over channels.
// How far about the middle in slope (candidates) the step from baseboard to reflection is sought.
constexpr double kMaxMiddleOffset = 3.0;
// The lowest baseboard, relative to the camera's height (5 cm at 1.2 m, 6.4 cm at 1.6 m), that
// FindJunctionBelowBandTop reads under a line: a thinner band along the wall is a tile joint's
// strip or the floor darkening toward the wall.
constexpr double kMinBaseboardRelativeHeight = 0.04;

double L1(const cv::Vec3d& c) { return std::abs(c[0]) + std::abs(c[1]) + std::abs(c[2]); }

// The mean colours along the lines through the vanishing point turned from a junction by k
// candidates (kStepDeg apart; negative: toward the wall), k in [first, last], each over the same
// points of the nearer part of the junction's extent: those where every line stays in the image.
class TurnedProfile {
 public:
  bool Read(const cv::Mat& image, const JunctionLine& junction, const Eigen::Vector2d& vp,
            bool left, int first, int last) {
    Eigen::Vector2d down = junction.near_end - vp;
    const double r_near = down.norm();
    if (!(r_near > 1)) return false;
    down /= r_near;
    const double r_far = std::max(0.0, (junction.far_end - vp).dot(down));
    if (!(r_near > r_far + 8)) return false;
    below = std::atan2(down.y(), std::abs(down.x()));
    const double step = kStepDeg * M_PI / 180.0;
    const auto direction = [&](int k) { return TurnedDown(down, left, k * step); };
    const Eigen::Vector2d first_end = direction(first), last_end = direction(last);
    const double r_start = std::max(r_far, r_near - kNearPart * (r_near - r_far));
    radii_.clear();
    for (int i = 0; i < kSamples; ++i) {
      const double r = r_start + (r_near - r_start) * (i + 0.5) / kSamples;
      if (InsideRoi(image, 0, vp + r * first_end) && InsideRoi(image, 0, vp + r * last_end)) {
        radii_.push_back(r);
      }
    }
    if (radii_.size() < 8) return false;
    first_ = first;
    last_ = last;
    colours_.assign(static_cast<size_t>(last - first + 1), cv::Vec3d(0, 0, 0));
    for (int k = first; k <= last; ++k) {
      colours_[static_cast<size_t>(k - first)] = MeanColourAlong(image, 0, vp, direction(k), radii_);
    }
    return true;
  }
  int first() const { return first_; }
  int last() const { return last_; }
  cv::Vec3d At(int k) const { return colours_[static_cast<size_t>(k - first_)]; }
  cv::Vec3d Mean(int from, int to) const {
    cv::Vec3d sum(0, 0, 0);
    for (int k = from; k <= to; ++k) sum += At(k);
    return sum / static_cast<double>(to - from + 1);
  }
  // The change at candidate k: the two beyond it toward the wall against the two toward the floor.
  double ChangeAt(int k) const { return L1((At(k - 1) + At(k - 2)) - (At(k + 1) + At(k + 2))); }
  // The largest change in [from, to] (clamped to where it is defined) and where; 0 when none.
  int LargestChange(int from, int to, double* change) const {
    int where = 0;
    *change = 0;
    for (int k = std::max(from, first_ + 2); k <= std::min(to, last_ - 2); ++k) {
      if (ChangeAt(k) > *change) *change = ChangeAt(k), where = k;
    }
    return where;
  }

  double below = 0;  // The junction's angle below the horizontal through the vanishing point, rad.

 private:
  int first_ = 0, last_ = 0;
  std::vector<double> radii_;
  std::vector<cv::Vec3d> colours_;
};

// The middle in slope, in candidates from the line `below` radians below the horizontal, of the
// band between that line and candidate `top` (negative: toward the wall, the band's top; positive:
// toward the floor, its lower edge).
double MiddleInSlope(double below, int top) {
  const double step = kStepDeg * M_PI / 180.0;
  const double below_top = below + top * step;
  const double middle_angle = std::atan(0.5 * (std::tan(below) + std::tan(below_top)));
  return (middle_angle - below) / step;
}

// Whether the profile's band from candidate `top` to `bottom` reads as a baseboard above its
// reflection, meeting at `middle` (fractional candidates): wall, baseboard, reflection, floor. The
// floor beside the reflection mirrors the wall above the baseboard, so the step from the floor to
// the reflection is the step from the wall to the baseboard, scaled by the floor's gloss; the
// reflection, a blend of the floor and the baseboard, is unlike the baseboard itself (a baseboard
// above a true junction is alike); and at the middle the band changes by most of the change from
// baseboard to reflection. `bottom_edge`: the band must also end at `bottom` (when no detected
// line says that it does).
bool ReadsAsReflection(const TurnedProfile& p, int top, double middle, int bottom,
                       bool bottom_edge, double max_gloss_residual) {
  const int m = static_cast<int>(std::lround(middle));
  if (m - 2 < top + 2 || m + 2 > bottom - 2 || bottom + kFloorSteps > p.last()) return false;
  const cv::Vec3d wall = p.Mean(std::max(p.first(), top - 6), top - 2);
  const cv::Vec3d board = p.Mean(top + 2, m - 2), mirror = p.Mean(m + 2, bottom - 2);
  const cv::Vec3d floor = p.Mean(bottom + 2, bottom + kFloorSteps);
  const cv::Vec3d span = board - wall;
  const double contrast = L1(span);
  if (contrast < kMinContrast) return false;
  const double gloss = (mirror - floor).dot(span) / span.dot(span);
  if (gloss < kMinGloss || gloss > kMaxGloss) return false;
  const double unlike = L1(mirror - board);
  if (L1(mirror - floor - gloss * span) > max_gloss_residual * contrast ||
      unlike < std::max(kMinUnlikeLevels, kMinUnlike * contrast)) {
    return false;
  }
  // ChangeAt sums two candidates on each side: twice the step between two flat bands, so a
  // change of at least `unlike` is at least half of it. Elsewhere in the band a door's or a
  // joint's reflection may change it as much: only the middle is asked for a step. The search
  // keeps clear of the blur of the band's two edges.
  double middle_change = 0;
  p.LargestChange(std::max(top + 5, static_cast<int>(std::floor(middle - kMaxMiddleOffset))),
                  std::min(bottom - 5, static_cast<int>(std::ceil(middle + kMaxMiddleOffset))),
                  &middle_change);
  if (middle_change < unlike) return false;
  if (!bottom_edge) return true;
  double bottom_change = 0;
  p.LargestChange(bottom - static_cast<int>(kMaxMiddleOffset),
                  bottom + static_cast<int>(kMaxMiddleOffset), &bottom_change);
  return bottom_change >= L1(mirror - floor);
}

// An 8-bit BGR image, a finite vanishing point and a turn in (1, 30] degrees: what the profiles
// can be read from.
bool CanRead(const cv::Mat& image, const Eigen::Vector2d& vanishing_point, double max_turn_deg) {
  return !image.empty() && image.type() == CV_8UC3 && vanishing_point.allFinite() &&
         max_turn_deg > 1 && max_turn_deg <= 30;
}

// The profile about `junction` from max_turn_deg toward the wall to `floor_steps` toward the floor,
// and the band's top in it: the largest change toward the wall. False when there is none.
bool ReadBandTop(const cv::Mat& image, const JunctionLine& junction,
                 const Eigen::Vector2d& vanishing_point, bool left, double max_turn_deg,
                 int floor_steps, TurnedProfile* profile, int* top) {
  if (!CanRead(image, vanishing_point, max_turn_deg)) return false;
  const int wall_steps = static_cast<int>(max_turn_deg / kStepDeg);
  if (!profile->Read(image, junction, vanishing_point, left, -wall_steps, floor_steps)) {
    return false;
  }
  double top_step = 0;
  *top = profile->LargestChange(-wall_steps + 2, -kMinBandSteps, &top_step);
  if (*top == 0) return false;
  const double max_slope = kMaxSlopeDeg * M_PI / 180.0;
  const double step = kStepDeg * M_PI / 180.0;
  return profile->below + *top * step > 0 && profile->below < max_slope;
}

}  // namespace

bool FindReflectedJunction(const cv::Mat& image, const JunctionLine& junction,
                           const Eigen::Vector2d& vanishing_point, bool left, double max_turn_deg,
                           double* turn_deg, double max_gloss_residual) {
  thread_local TurnedProfile profile;
  int top = 0;
  if (!ReadBandTop(image, junction, vanishing_point, left, max_turn_deg, kFloorSteps, &profile,
                   &top)) {
    return false;
  }
  // The middle in slope of the band from its top to the junction, its lower edge.
  const double step = kStepDeg * M_PI / 180.0;
  const double below = profile.below;
  double middle = MiddleInSlope(below, top);
  if (!ReadsAsReflection(profile, top, middle, 0, false, max_gloss_residual)) {
    // A reflection much darker than its baseboard makes the junction itself the largest change:
    // the band's top is then the largest change beyond it, toward the wall.
    double change = 0;
    const int wall_steps = static_cast<int>(max_turn_deg / kStepDeg);
    top = profile.LargestChange(-wall_steps + 2, top - kMinBandSteps, &change);
    if (top == 0 || !(below + top * step > 0)) return false;
    middle = MiddleInSlope(below, top);
    if (!ReadsAsReflection(profile, top, middle, 0, false, max_gloss_residual)) return false;
  }
  *turn_deg = middle * kStepDeg;
  return true;
}

bool FindJunctionBelowBandTop(const cv::Mat& image, const JunctionLine& top,
                              const Eigen::Vector2d& vanishing_point, bool left,
                              double max_turn_deg, double* turn_deg) {
  if (!CanRead(image, vanishing_point, max_turn_deg)) return false;
  // The profile from the wall above `top` (its colour) down past the farthest reflection's lower
  // edge, and the floor beyond it.
  thread_local TurnedProfile profile;
  const int floor_steps = static_cast<int>(max_turn_deg / kStepDeg);
  if (!profile.Read(image, top, vanishing_point, left, -8, floor_steps + kFloorSteps)) {
    return false;
  }
  if (!(profile.below < kMaxSlopeDeg * M_PI / 180.0)) return false;
  // The reflection's lower edge: the largest change toward the floor.
  double change = 0;
  const int bottom = profile.LargestChange(2 * kMinBandSteps, floor_steps, &change);
  if (bottom == 0) return false;
  // The junction: the middle in slope of the band from `top` (0) to `bottom`.
  const double step = kStepDeg * M_PI / 180.0;
  const double below = profile.below;
  const double middle = MiddleInSlope(below, bottom);
  // The baseboard's height relative to the camera's: a wall line at height z has a slope in
  // proportion to h - z.
  if (1.0 - std::tan(below) / std::tan(below + middle * step) < kMinBaseboardRelativeHeight) {
    return false;
  }
  if (!ReadsAsReflection(profile, 0, middle, bottom, true, kMaxGlossResidual)) return false;
  *turn_deg = middle * kStepDeg;
  return true;
}

bool BandAboveJunction(const cv::Mat& image, const JunctionLine& junction,
                       const Eigen::Vector2d& vanishing_point, bool left, double max_turn_deg,
                       double* relative_height, double* middle_turn_deg) {
  thread_local TurnedProfile profile;
  int top = 0;
  if (!ReadBandTop(image, junction, vanishing_point, left, max_turn_deg, kFloorSteps, &profile,
                   &top)) {
    return false;
  }
  // The band's top is a baseboard's: as unlike the wall above it as a reflection's band needs.
  const cv::Vec3d wall = profile.Mean(std::max(profile.first(), top - 6), top - 2);
  const cv::Vec3d board = profile.Mean(top + 2, std::min(top + 6, -2));
  if (L1(board - wall) < kMinContrast) return false;
  const double step = kStepDeg * M_PI / 180.0;
  const double below = profile.below;
  *relative_height = 1.0 - std::tan(below + top * step) / std::tan(below);
  *middle_turn_deg = MiddleInSlope(below, top) * kStepDeg;
  return true;
}

bool JunctionAtReflectedBandsMiddle(const cv::Mat& image, const JunctionLine& junction,
                                    const Eigen::Vector2d& vanishing_point, bool left,
                                    double max_turn_deg) {
  // The reflection's lower edge lies less far toward the floor than the baseboard's top toward
  // the wall (the tangent grows faster than the angle): the profile reaches as far beyond the
  // junction as before it, and the floor beyond.
  thread_local TurnedProfile profile;
  const int reach = static_cast<int>(max_turn_deg / kStepDeg) + kFloorSteps;
  int top = 0;
  if (!ReadBandTop(image, junction, vanishing_point, left, max_turn_deg, reach, &profile, &top)) {
    return false;
  }
  // The reflection's lower edge, as far below the junction in slope as the top is above it.
  const double step = kStepDeg * M_PI / 180.0;
  const double below = profile.below, below_top = below + top * step;
  const double bottom_angle = std::atan(2 * std::tan(below) - std::tan(below_top));
  const int bottom = static_cast<int>(std::lround((bottom_angle - below) / step));
  return ReadsAsReflection(profile, top, 0.0, bottom, true, kMaxGlossResidual);
}

}  // namespace corridor
