#include "pipeline/inner_line_check.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <vector>

#include <Eigen/Geometry>

#include "corridor_depth/corridor_frame.h"
#include "perception/appearance.h"
#include "perception/corridor_projection.h"
#include "perception/line_segments.h"

namespace corridor {
namespace {

// The image line of the floor line (x, h, z) over the depths where it is in view, as the junction
// search's lines are held (MergedLine); false when fewer than two of its samples are in view.
bool FloorLineInImage(const Camera& camera, const CorridorGeometry& g, double x, MergedLine* m) {
  const CorridorRotation<double> r(g.pitch, g.yaw);
  const bool distorted = camera.HasDistortion();
  std::vector<Eigen::Vector2d> points;
  // From 1 m to 12 m, evenly in inverse distance: the near part, where a baseboard is tallest.
  constexpr int kSamples = 32;
  for (int i = 0; i < kSamples; ++i) {
    const double inverse = 1.0 + (1.0 / 12.0 - 1.0) * i / (kSamples - 1);
    cv::Point p;
    if (ProjectCorridorPoint(camera, distorted, r, x, g.camera_height, 1.0 / inverse, 2, &p)) {
      points.emplace_back(p.x, p.y);
    }
  }
  if (points.size() < 2) return false;
  Eigen::Vector3d line = points.front().homogeneous().cross(points.back().homogeneous());
  const double norm = line.head<2>().norm();
  if (!(norm > 1e-9)) return false;
  line /= norm;
  if (line.y() < 0) line = -line;
  m->line = line;
  SetExtentAlongLine(points, m);
  return true;
}

// How unlike the floor below it the band between the floor lines at wall distances `upper` and
// `lower` (< upper) on `side` (0 left, 1 right) looks (BandContrast); -1 when not measurable.
double WallBand(const cv::Mat& bgr, const Camera& camera, const CorridorGeometry& g, int side,
                double upper, double lower, const FloorAppearance& floor) {
  const double sign = side == 0 ? -1.0 : 1.0;
  MergedLine up, down;
  if (!FloorLineInImage(camera, g, sign * upper, &up) ||
      !FloorLineInImage(camera, g, sign * lower, &down)) {
    return -1;
  }
  return BandContrast(bgr, floor, up, down, 0);
}

}  // namespace

bool InnerLineCheckOptions::Check(std::string* why) const {
  std::string reason;
  if (!(min_disagreement > 0 && std::isfinite(min_disagreement))) {
    reason = "min_disagreement must be positive";
  } else if (!(min_support > 0 && min_support <= 1) ||
             !(strong_support > 0 && strong_support <= 1)) {
    reason = "min_support and strong_support must be in (0, 1]";
  } else if (!(min_above_camera > 0 && std::isfinite(min_above_camera))) {
    reason = "min_above_camera must be positive";
  } else if (!(max_line_support > 0 && max_line_support <= 1)) {
    reason = "max_line_support must be in (0, 1]";
  }
  if (!(min_band_contrast >= 0 && std::isfinite(min_band_contrast))) {
    reason = "min_band_contrast must be non-negative";
  } else if (!(min_baseboard_disagreement > 0 && std::isfinite(min_baseboard_disagreement))) {
    reason = "min_baseboard_disagreement must be positive";
  } else if (!(min_target_support >= 0 && min_target_support <= 1)) {
    reason = "min_target_support must be in [0, 1] (0 = no check)";
  } else if (!(max_baseboard_height >= 0 && std::isfinite(max_baseboard_height))) {
    reason = "max_baseboard_height must be >= 0 (0 = no limit)";
  } else if (!(far_max_height >= 0 && std::isfinite(far_max_height))) {
    reason = "far_max_height must be >= 0 m (0 = never)";
  } else if (!(min_far_ceiling_support > 0 && min_far_ceiling_support <= 1) ||
             !(min_far_target_support >= 0 && min_far_target_support <= 1)) {
    reason = "min_far_ceiling_support must be in (0, 1], min_far_target_support in [0, 1]";
  }
  if (reason.empty()) return true;
  if (why != nullptr) *why = reason;
  return false;
}

double MinInnerLineDisagreement(const InnerLineCheckOptions& options) {
  return options.min_band_contrast > 0
             ? std::min(options.min_disagreement, options.min_baseboard_disagreement)
             : options.min_disagreement;
}

std::string DescribeInnerLineCheck(const InnerLineCheck& check) {
  if (!check.moved) return "";
  std::ostringstream how;
  const int other = 1 - check.side;
  if (check.far) {
    how << (check.side == 0 ? "left" : "right") << " wall moved in " << std::setprecision(3)
        << check.factor << "x: its junction is a line beyond the wall (a room's seen through "
        << "glass, or a recess's): where it stood, its ceiling junction would be "
        << check.side_height[check.side] << " m high, above any ceiling searched; moved in, it "
        << "meets the other side's (" << check.side_height[other]
        << " m), and its new junction is on edges over " << std::setprecision(2)
        << check.target_support << " of its view";
    return how.str();
  }
  how << (check.side == 0 ? "left" : "right") << " wall moved "
      << (check.baseboard ? "in " : "out ") << std::setprecision(3) << check.factor
      << "x: its junction is "
      << (check.baseboard ? "a line on the wall, as a baseboard's top is"
                          : "a line inside the floor")
      << " (its ceiling junction gave "
      << check.side_height[check.side] << " m, the other side's " << check.side_height[other]
      << " m; its new junction on edges over " << std::setprecision(2) << check.target_support
      << " of its view)";
  return how.str();
}

InnerLineCheck CheckInnerLine(const cv::Mat& bgr, const Camera& camera,
                              const CeilingDetectorOptions& ceiling,
                              const InnerLineCheckOptions& options, CorridorGeometry* geometry,
                              ImageEdges* edges, std::array<bool, 2> has_lower,
                              std::array<bool, 2> at_reflected_band) {
  InnerLineCheck check;
  const double h = geometry->camera_height;
  CeilingDetectorOptions wide = ceiling;
  // The side too near gives the lower ceiling, the other one at most max_height.
  wide.min_height = h + options.min_above_camera;
  if (!(wide.max_height > wide.min_height)) return check;
  CeilingEstimate sides;
  if (!DetectCeiling(bgr, camera, *geometry, wide, &sides, edges).ok()) return check;
  for (int s = 0; s < 2; ++s) {
    check.side_height[s] = sides.side_height[s];
    check.side_support[s] = sides.side_support[s];
  }
  // Each side's ceiling above the camera: proportional to its wall's distance.
  const double above[2] = {sides.side_height[0] - h, sides.side_height[1] - h};
  if (!(above[0] > 0) || !(above[1] > 0)) return check;
  const int inner = above[0] < above[1] ? 0 : 1;
  // Both sides on at least half their samples; or, where the trusted side's junction shows only
  // from a few metres on, that side on its samples in view and the side to move strong (a wall put
  // too near sees its ceiling junction, scaled down, over most of the samples).
  const bool both = sides.side_support[0] >= options.min_support &&
                    sides.side_support[1] >= options.min_support;
  const bool narrow_view = sides.side_visible_support[1 - inner] >= options.min_support &&
                           sides.side_support[inner] >= options.strong_support &&
                           !has_lower[1 - inner];
  if (!both && !narrow_view) return check;
  const double factor = above[1 - inner] / above[inner];
  double distance[2] = {geometry->LeftDistance(), geometry->RightDistance()};
  // A baseboard's top taken on the far side: its junction is the floor's boundary (BoundaryScore)
  // best placed a little further in, about the ceiling sides' ratio; the bands the two moves would
  // cross, from the far wall's line in to that junction and from the near wall's line out by the
  // same ratio, are both baseboard (unlike the floor below them), where moving the near wall out
  // would cross floor.
  if (options.min_band_contrast > 0 && factor > 1 + options.min_baseboard_disagreement &&
      sides.side_height[inner] >= ceiling.min_height &&
      sides.side_height[inner] <= ceiling.max_height) {
    const int outer = 1 - inner;
    const FloorAppearance floor = SampleFloor(bgr, 0);
    double best_score = 0, ratio = 0;
    for (double r = std::max(1.04, factor / 1.1); r <= 1.1 * factor; r += 0.01) {
      MergedLine line;
      const double x = distance[outer] / r;
      if (!FloorLineInImage(camera, *geometry, outer == 0 ? -x : x, &line)) continue;
      const double score = BoundaryScore(bgr, floor, line, 0);
      if (score > best_score) {
        best_score = score;
        ratio = r;
      }
    }
    if (ratio > 0) {
      check.band_contrast[inner] = WallBand(bgr, camera, *geometry, inner,
                                            distance[inner] * ratio, distance[inner], floor);
      check.band_contrast[outer] = WallBand(bgr, camera, *geometry, outer, distance[outer],
                                            distance[outer] / ratio, floor);
    }
    if (check.band_contrast[inner] >= options.min_band_contrast &&
        check.band_contrast[outer] >= options.min_band_contrast) {
      // Two measures of one ratio, the ceiling sides' and the floor boundary's: their mean.
      const double move = std::sqrt(ratio * factor);
      distance[outer] /= move;
      // A baseboard's top puts its wall too far by h / (h - b) at most, b its height above the
      // floor; and the junction below it shows on edges.
      const double b = options.max_baseboard_height;
      if (b > 0 && h > b && move > h / (h - b)) return check;
      check.target_support = BestFloorLineSupportNear(
          bgr, camera, *geometry, outer == 0 ? -distance[outer] : distance[outer], 1.08, ceiling,
          edges);
      if (check.target_support < options.min_target_support) return check;
      geometry->SetWallDistances(distance[0], distance[1]);
      check.moved = true;
      check.baseboard = true;
      check.side = outer;
      check.factor = 1 / move;
      return check;
    }
  }
  const double trusted = sides.side_height[1 - inner];
  if (!(factor > 1 + options.min_disagreement) || trusted < ceiling.min_height ||
      trusted > ceiling.max_height) {
    return check;
  }
  // A junction at a baseboard-and-reflection band's middle has a faint edge of its own, and the
  // baseboard's top just above it, where a move out would put it.
  if (at_reflected_band[inner]) return check;
  // A box's edge or a floor line taken for the junction follows edges over part of the way; a line
  // on edges nearly all along, as a junction is, stays (the other wall is then the wrong one: put
  // too far, which this check cannot tell from this one put too near).
  const double wall_x = inner == 0 ? -geometry->LeftDistance() : geometry->RightDistance();
  check.line_support =
      CorridorLineSupport(bgr, camera, *geometry, wall_x, h, ceiling, edges);
  if (check.line_support >= options.max_line_support) return check;
  distance[inner] *= factor;
  // The true junction shows on edges somewhere along its view, between the boxes that hid it; a
  // wall's plain face (where a correct wall would be moved out to) does not.
  check.target_support = BestFloorLineSupportNear(
      bgr, camera, *geometry, inner == 0 ? -distance[inner] : distance[inner], 1.08, ceiling, edges);
  if (check.target_support < options.min_target_support) return check;
  geometry->SetWallDistances(distance[0], distance[1]);
  check.moved = true;
  check.side = inner;
  check.factor = factor;
  return check;
}

}  // namespace corridor
