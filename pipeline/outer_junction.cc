#include "pipeline/outer_junction.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <Eigen/Geometry>

#include "perception/appearance.h"
#include "perception/junction_refit.h"
#include "perception/support_extent.h"

namespace corridor {
namespace {

constexpr double kDegree = M_PI / 180.0;
// A segment points at the vanishing point when its direction and the direction from the vanishing
// point to its middle differ by at most this.
constexpr double kMaxAim = 2.0 * kDegree;
// The outer line turns outward from the chosen one about the vanishing point by at least this
// (an object's depth before the wall), and at most this (beyond it, the wall's upper lines).
constexpr double kMinTurn = 1.0 * kDegree;
constexpr double kMaxTurn = 25.0 * kDegree;
// Segments within this angle of each other about the vanishing point are one line's.
constexpr double kGroupWidth = 1.5 * kDegree;
// A group's segments together at least this long, as a fraction of the image height.
constexpr double kMinSupport = 0.1;
// The outer line's edge points have the floor below them, on the whole at least this like it
// (appearance.h's floor-likeness): where it is seen it is the floor's edge, not an object's top,
// whose face below is unlike the floor (likeness near 0).
constexpr double kMinFloorBelow = 0.25;
// Segment ends closer to the vanishing point than this (px) are too close to tell lines apart.
constexpr double kMinVpDistance = 10.0;

double Cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// A segment on the wall's side: its outward turn about the vanishing point, its length and its
// ends' positions along the chosen line's direction.
struct WallSegment {
  double turn = 0;
  double length = 0;
  double near = 0, far = 0;
};

// The line through the vanishing point `v` along the segments [begin, end) (their length-weighted
// turn from `d0`), refitted on the image's colour edges over their extent; false when the refit
// fails.
bool LineOfGroup(const WallSegment* begin, const WallSegment* end, const Eigen::Vector2d& v,
                 const Eigen::Vector2d& d0, double outward, const cv::Mat& bgr,
                 JunctionLine* line) {
  double weighted_turn = 0, weight = 0, near = 0, far = std::numeric_limits<double>::infinity();
  for (const WallSegment* w = begin; w != end; ++w) {
    weighted_turn += w->length * w->turn;
    weight += w->length;
    near = std::max(near, w->near);
    far = std::min(far, w->far);
  }
  const double turn = outward * weighted_turn / weight;
  const Eigen::Vector2d d(std::cos(turn) * d0.x() - std::sin(turn) * d0.y(),
                          std::sin(turn) * d0.x() + std::cos(turn) * d0.y());
  const Eigen::Vector2d n(-d.y(), d.x());
  line->line = Eigen::Vector3d(n.x(), n.y(), -n.dot(v));
  line->near_end = v + near * d;
  line->far_end = v + far * d;
  return RefitJunctionAtFullResolution(bgr, JunctionRefitOptions(), line);
}

// The unit normal of `line` toward the floor: toward the chosen line, whose direction from the
// vanishing point is `d0`.
Eigen::Vector2d FloorwardNormal(const Eigen::Vector3d& line, const Eigen::Vector2d& d0) {
  const Eigen::Vector2d n = line.head<2>().normalized();
  return n.dot(d0) < 0 ? Eigen::Vector2d(-n) : n;
}

// The support's length in whole pixels along the line, and the confidence the detector gives a
// line of that length with the boundary score of the line it replaces (support_extent.h).
void SetConfidence(const JunctionLine& chosen, int image_rows, JunctionLine* line) {
  std::vector<int> bins;
  line->support_length = MeasureSupport(line->support, line->line, &bins).covered;
  // The chosen line's boundary score: its confidence over its length's factor.
  const double chosen_length = JunctionConfidence(1.0, chosen.support_length, image_rows);
  const double boundary = chosen_length > 0 ? std::min(1.0, chosen.confidence / chosen_length) : 0;
  line->confidence = JunctionConfidence(boundary, line->support_length, image_rows);
}

}  // namespace

bool FindOuterJunction(const JunctionPair& junctions, int side, const cv::Mat& bgr, int scale,
                       JunctionLine* outer) {
  if (!junctions.status.ok() || bgr.empty() || (side != 0 && side != 1)) return false;
  const JunctionLine& chosen = side == 0 ? junctions.left : junctions.right;
  const JunctionLine& other = side == 0 ? junctions.right : junctions.left;
  const Eigen::Vector2d v = junctions.vanishing_point;
  if (!v.allFinite()) return false;
  const Eigen::Vector2d to_near = chosen.near_end - v;
  if (!(to_near.norm() > kMinVpDistance)) return false;
  const Eigen::Vector2d d0 = to_near.normalized();
  // Turns toward the other junction are toward the floor; outward is the other way.
  const double outward = Cross(d0, other.near_end - v) > 0 ? -1.0 : 1.0;
  const auto turn_of = [&](const Eigen::Vector2d& p) {
    const Eigen::Vector2d q = p - v;
    return outward * std::atan2(Cross(d0, q), d0.dot(q));
  };

  std::vector<WallSegment> found;
  for (const cv::Vec4f& s : junctions.segments) {
    const Eigen::Vector2d a(s[0], s[1]), b(s[2], s[3]);
    const Eigen::Vector2d along = b - a;
    const double length = along.norm();
    if (!(length > 1.0)) continue;
    const double ta = turn_of(a), tb = turn_of(b);
    if (std::min(ta, tb) < kMinTurn || std::max(ta, tb) > kMaxTurn) continue;
    if (d0.dot(a - v) < kMinVpDistance || d0.dot(b - v) < kMinVpDistance) continue;
    const Eigen::Vector2d mid = 0.5 * (a + b) - v;
    const double aim = std::abs(Cross(along, mid)) / (length * mid.norm());
    if (!(aim <= std::sin(kMaxAim))) continue;
    WallSegment w;
    w.turn = turn_of(0.5 * (a + b));
    w.length = length;
    w.near = std::max((a - v).norm(), (b - v).norm());
    w.far = std::min((a - v).norm(), (b - v).norm());
    found.push_back(w);
  }
  if (found.empty()) return false;
  std::sort(found.begin(), found.end(),
            [](const WallSegment& x, const WallSegment& y) { return x.turn < y.turn; });
  const FloorAppearance floor = SampleFloor(bgr, 0, 2 * std::max(1, scale));
  // The groups, nearest the chosen line first: the first with enough length whose line has the
  // floor below its edges.
  const double min_length = kMinSupport * bgr.rows;
  for (size_t first = 0; first < found.size();) {
    double total = 0;
    size_t last = first;
    for (; last < found.size() && found[last].turn - found[first].turn <= kGroupWidth; ++last) {
      total += found[last].length;
    }
    if (total < min_length) {
      ++first;
      continue;
    }
    JunctionLine line;
    if (LineOfGroup(found.data() + first, found.data() + last, v, d0, outward, bgr, &line) &&
        FloorLikenessBelow(bgr, floor, line.support, FloorwardNormal(line.line, d0), 0,
                           scale) >= kMinFloorBelow) {
      SetConfidence(chosen, bgr.rows, &line);
      *outer = std::move(line);
      return true;
    }
    first = last;
  }
  return false;
}

bool ReplaceJunction(int side, JunctionLine line, JunctionPair* pair) {
  const Eigen::Vector3d& other = (side == 0 ? pair->right : pair->left).line;
  const Eigen::Vector3d vp = line.line.cross(other);
  if (!(std::abs(vp.z()) > 1e-12) || (side != 0 && side != 1)) return false;
  pair->vanishing_point = vp.hnormalized();
  (side == 0 ? pair->left : pair->right) = std::move(line);
  (side == 0 ? pair->has_left_lower : pair->has_right_lower) = false;
  return true;
}

}  // namespace corridor
