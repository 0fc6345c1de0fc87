#include "pipeline/floor_beyond_junction.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/round_half_away.h"
#include "corridor_depth/corridor_frame.h"

namespace corridor {
namespace {

// Offsets across the line, in search pixels, of the colours compared on each side (clear of the
// edge's own blur).
constexpr double kNear = 2.0, kFar = 4.0;
// The line is examined up to this far (search pixels) from the vanishing point, where the lines
// and the objects along them are too close to tell apart.
constexpr double kMinVpDistance = 10.0;
// How far across the line (search pixels) a support pixel of the line counts as on it.
constexpr double kSupportReach = 2.0;
// A point of the line where the contrast across it is below kFlatContrast of the line's own, and
// whose two sides differ from the floor's middle by less than kFloorLike of it, has the floor on
// both sides.
constexpr double kFlatContrast = 0.25, kFloorLike = 0.25;
// Such points count in runs (broken by at most kMaxGap points) at least kMinRunLength long along
// the corridor, m: a doorway's floor, open to the corridor, is shorter.
constexpr int kMaxGap = 4;
constexpr double kMinRunLength = 2.0;

// One point of the line: the contrast across it, how far its two sides are from the floor's
// middle at its row, its distance along the corridor (m; -1 above the horizon), and whether the
// line has edge support there.
struct Sample {
  double across = 0;
  double floor_change = 0;
  double depth = -1;
  bool on_support = false;
};

// The mean colour of the pixels from `p + near n` to `p + far n` (1 px steps, nearest pixel);
// false when one falls outside the image.
bool SideColour(const cv::Mat& bgr, const Eigen::Vector2d& p, const Eigen::Vector2d& n,
                cv::Vec3d* colour) {
  // Integer sums: the same as doubles added in order (whole numbers far below 2^53).
  int sum[3] = {0, 0, 0};
  int count = 0;
  for (double d = kNear; d <= kFar + 1e-9; d += 1.0) {
    const int u = RoundHalfAway(p.x() + d * n.x());
    const int v = RoundHalfAway(p.y() + d * n.y());
    if (static_cast<unsigned>(u) >= static_cast<unsigned>(bgr.cols) ||
        static_cast<unsigned>(v) >= static_cast<unsigned>(bgr.rows)) {
      return false;
    }
    const uchar* c = bgr.ptr<uchar>(v) + 3 * u;
    sum[0] += c[0];
    sum[1] += c[1];
    sum[2] += c[2];
    ++count;
  }
  *colour = cv::Vec3d(sum[0], sum[1], sum[2]) * (1.0 / count);
  return true;
}

double Distance(const cv::Vec3d& a, const cv::Vec3d& b) {
  return std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) + std::abs(a[2] - b[2]);
}

}  // namespace

FloorBeyond MeasureFloorBeyond(const WorkingImage& search, const CorridorGeometry& geometry,
                               const JunctionLine& line, const JunctionLine& other,
                               const Eigen::Vector2d& vp) {
  FloorBeyond out;
  const cv::Mat& bgr = search.bgr;
  const int scale = search.scale;
  if (bgr.empty() || bgr.type() != CV_8UC3 || scale < 1) return out;
  const CorridorRotation<double> rotation(geometry.pitch, geometry.yaw);
  // The distance along the corridor of the floor point seen at a search pixel (-1 above the
  // horizon).
  const auto floor_depth = [&](const Eigen::Vector2d& p) {
    const Vec3<double> c = rotation.ToCorridor(RayOfRawPixel(search.camera, p.x(), p.y()));
    return c.y > 1e-9 ? geometry.camera_height * c.z / c.y : -1.0;
  };
  const double s = 1.0 / scale;
  const Eigen::Vector2d near_end = line.near_end * s, v = vp * s;
  if (!v.allFinite()) return out;
  const Eigen::Vector2d to_vp = v - near_end;
  // Up to kMinVpDistance from the vanishing point, and never longer than the image's diagonal.
  const double length = std::min(to_vp.norm() - kMinVpDistance, std::hypot(bgr.cols, bgr.rows));
  if (!(length > 4 * kFar)) return out;
  const Eigen::Vector2d dir = to_vp.normalized();
  // The wall side: away from the other junction (which lies on the floor's side).
  Eigen::Vector2d n(-dir.y(), dir.x());
  if (n.dot(other.near_end * s - near_end) > 0) n = -n;
  // The floor is known to go on only as far as the other junction's support: floor points at one
  // depth share an image row (no roll), so the line is examined up to that row.
  const double stop_row = other.far_end.y() * s;

  // The other junction's column at a row (its line a u + b v + c = 0, in search pixels).
  const Eigen::Vector3d& o = other.line;
  if (!(std::abs(o.x()) > 1e-6)) return out;
  const auto other_u = [&](double row) { return -(o.y() * row * scale + o.z()) / o.x() * s; };

  // Per-thread buffers, kept from call to call.
  thread_local std::vector<char> supported;
  thread_local std::vector<Sample> samples;
  thread_local std::vector<double> sorted;

  // Where the line has edge support of its own: an edge there, however faint, is a boundary.
  supported.assign(static_cast<size_t>(length) + 2, 0);
  for (const Eigen::Vector2d& raw : line.support) {
    const Eigen::Vector2d q = raw * s - near_end;
    if (std::abs(q.dot(n)) > kSupportReach) continue;
    const long at = std::lround(q.dot(dir));
    for (long k = at - 1; k <= at + 1; ++k) {
      if (k >= 0 && k < static_cast<long>(supported.size())) supported[static_cast<size_t>(k)] = 1;
    }
  }

  samples.clear();
  for (double t = 0; t <= length; t += 1.0) {
    const Eigen::Vector2d p = near_end + t * dir;
    if (p.y() < stop_row) break;
    const double depth = floor_depth(p);
    // Beyond the end wall the line runs up the end wall, as does the floor's middle at its row.
    if (geometry.HasEndWall() && depth > geometry.end_distance) break;
    cv::Vec3d wall, floor, middle;
    if (!SideColour(bgr, p, n, &wall) || !SideColour(bgr, p, -n, &floor)) continue;
    // The floor at the same depth: the middle of the floor between the two junctions, same row.
    const Eigen::Vector2d mid(0.5 * (p.x() + other_u(p.y())), p.y());
    if (!SideColour(bgr, mid, Eigen::Vector2d(0, 1), &middle)) continue;
    Sample sample;
    sample.across = Distance(wall, floor);
    sample.floor_change = std::max(Distance(floor, middle), Distance(wall, middle));
    sample.depth = depth;
    sample.on_support = supported[static_cast<size_t>(t)] != 0;
    samples.push_back(sample);
  }
  const int count = static_cast<int>(samples.size());
  if (count < 10) return out;
  // The junction's own contrast: what the line shows where it is an edge (its upper quartile).
  sorted.clear();
  for (const Sample& sample : samples) sorted.push_back(sample.across);
  auto q = sorted.begin() + static_cast<std::ptrdiff_t>(3 * count / 4);
  std::nth_element(sorted.begin(), q, sorted.end());
  const double own = *q;
  if (!(own > 1e-6)) return out;
  // Runs of points with the floor on both sides (gaps of a few points allowed: grout or a shadow
  // crossing the line); only runs longer along the corridor than a doorway count.
  int floor_across = 0;
  int run_start = -1, run_last = -1, run_points = 0;
  const auto close_run = [&] {
    if (run_start >= 0 && samples[static_cast<size_t>(run_last)].depth -
                                  samples[static_cast<size_t>(run_start)].depth >=
                              kMinRunLength) {
      floor_across += run_points;
    }
    run_start = -1, run_points = 0;
  };
  for (int i = 0; i < count; ++i) {
    const Sample& sample = samples[static_cast<size_t>(i)];
    const bool floor_both_sides = !sample.on_support && sample.across < kFlatContrast * own &&
                                  sample.floor_change < kFloorLike * own && sample.depth > 0;
    if (!floor_both_sides) {
      if (run_start >= 0 && i - run_last > kMaxGap) close_run();
      continue;
    }
    if (run_start < 0) run_start = i;
    run_last = i;
    ++run_points;
  }
  close_run();
  out.samples = count;
  out.contrast = own;
  out.floor_across = static_cast<double>(floor_across) / count;
  return out;
}

}  // namespace corridor
