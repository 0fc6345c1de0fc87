#include "perception/junction_detector.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>
#include <vector>

#include <Eigen/Geometry>
#include <opencv2/imgproc.hpp>

#include "kernels/edge_scan.h"
#include "perception/appearance.h"
#include "perception/floor_texture.h"
#include "perception/junction_refit.h"
#include "perception/junction_selector.h"
#include "perception/line_segments.h"
#include "perception/robust_line_fit.h"
#include "perception/working_image.h"

namespace corridor {
namespace {

constexpr int kMinImageSide = 24;      // Smaller images cannot show a corridor.
constexpr long kMinFloorPixels = 200;  // Fewer floor pixels (working resolution) are too few to judge its texture.

// The points of `from` for which keep(p) holds, in order, into *to. Every point is written and
// the count advanced only for the kept ones: no branch on where the points lie, which edge maps
// make unpredictable.
template <typename Keep>
void KeepWhere(const std::vector<Eigen::Vector2d>& from, Keep keep,
               std::vector<Eigen::Vector2d>* to) {
  to->resize(from.size());
  size_t kept = 0;
  for (const auto& p : from) {
    (*to)[kept] = p;
    kept += static_cast<size_t>(keep(p));
  }
  to->resize(kept);
}

// The pixels of `side` within `distance` of the line, in order.
void SupportPixels(const std::vector<Eigen::Vector2d>& side, const Eigen::Vector3d& line,
                   double distance, std::vector<Eigen::Vector2d>* support) {
  KeepWhere(
      side, [&](const Eigen::Vector2d& p) {
        return !(std::abs(line.dot(p.homogeneous())) > distance);
      },
      support);
}

// The final JunctionLine: refit on nearby edge pixels, extent and confidence.
JunctionLine Refine(const JunctionCandidate& candidate, const std::vector<Eigen::Vector2d>& edges,
                    const Eigen::Vector2d& vp, bool left, double distance,
                    double image_height) {
  JunctionLine out;
  Eigen::Vector3d line = candidate.line.line;
  const std::vector<Eigen::Vector2d> side = FloorSidePixels(edges, vp, left);
  std::vector<Eigen::Vector2d> support, fitted;  // `fitted`: the pixels `line` was fitted to.
  bool final_support = false;                    // True once `support` is the final (distance, line) support.
  for (int round = 0; round < 3; ++round) {
    SupportPixels(side, line, round == 0 ? 2 * distance : distance, &support);
    // The same pixels give the same fit (FitLineLeastDistance is deterministic): the line has
    // converged.
    if (round > 0 && support == fitted) {
      final_support = true;
      break;
    }
    Eigen::Vector3d refit;
    if (!FitLineLeastDistance(support, &refit)) break;
    line = refit;
    fitted.swap(support);
  }
  if (!final_support) SupportPixels(side, line, distance, &support);
  out.line = line;
  const Eigen::Vector2d direction(line.y(), -line.x());
  const Eigen::Vector2d origin = -line.z() * line.head<2>();
  if (support.size() < 8) {
    support = {candidate.line.start, candidate.line.end};
  }
  double lo = 1e300, hi = -1e300;
  std::vector<int> bins;
  for (const auto& p : support) {
    const double t = (p - origin).dot(direction);
    lo = std::min(lo, t);
    hi = std::max(hi, t);
    bins.push_back(static_cast<int>(std::floor(t)));
  }
  std::sort(bins.begin(), bins.end());
  out.support_length = static_cast<double>(std::unique(bins.begin(), bins.end()) - bins.begin());
  const Eigen::Vector2d a = origin + lo * direction, b = origin + hi * direction;
  // The near end is the lower one (larger v).
  out.near_end = a.y() > b.y() ? a : b;
  out.far_end = a.y() > b.y() ? b : a;
  out.support = std::move(support);
  out.confidence = std::clamp(candidate.boundary, 0.0, 1.0) *
                   std::min(1.0, out.support_length / (0.25 * image_height));
  return out;
}

// The chosen lines' refit on the full-resolution image, when the search ran on a halved one
// (off: nothing to do).
struct FullResolutionRefit {
  bool on = false;
  const cv::Mat* bgr = nullptr;  // The full-resolution colour image.
  JunctionRefitOptions options;

  void Apply(JunctionLine* line) const {
    if (on) RefitJunctionAtFullResolution(*bgr, options, line);
  }
};

// The one visible junction when the other side has no candidate: the outermost line that looks
// like the floor's edge, refined on its edge pixels, and where the other lines (grout, baseboards, other
// wall lines along the corridor) meet it: the length-weighted median crossing above its support.
void KeepSingleJunction(const std::vector<JunctionCandidate>& side, bool is_left,
                        const std::vector<MergedLine>& lines,
                        const std::vector<Eigen::Vector2d>& edges,
                        const JunctionDetectorOptions& options, int height,
                        const FullResolutionRefit& refit, JunctionPair* result) {
  // Among the lines with floor below and something else above, the outermost: grout lines and
  // reflections lie inside the floor, baseboard tops and door bottoms have no floor below.
  double best_boundary = 0;
  for (const auto& c : side) best_boundary = std::max(best_boundary, c.boundary);
  const auto bottom_u = [&](const MergedLine& l) {  // u where the line meets the bottom row.
    return std::abs(l.line.x()) > 1e-9 ? -(l.line.y() * height + l.line.z()) / l.line.x() : 0.0;
  };
  size_t best = 0;
  bool found = false;
  for (size_t i = 0; i < side.size(); ++i) {
    if (side[i].boundary < std::max(0.3, 0.5 * best_boundary)) continue;
    const double u = bottom_u(side[i].line), best_u = bottom_u(side[best].line);
    if (!found || (is_left ? u < best_u : u > best_u)) best = i;
    found = true;
  }
  if (!found) return;  // No line looks like the floor's edge.
  const MergedLine& m = side[best].line;
  const Eigen::Vector2d top = m.start.y() < m.end.y() ? m.start : m.end;
  result->single = Refine(side[best], edges, top, is_left, options.support_distance_px,
                          height);
  refit.Apply(&result->single);
  result->single_is_left = is_left;
  result->has_single = true;
  // Crossings of the other lines with this one, above its support's far end.
  const Eigen::Vector3d& l = result->single.line;
  const Eigen::Vector2d direction(l.y(), -l.x());
  const Eigen::Vector2d origin = -l.z() * l.head<2>();
  const double far_t = (result->single.far_end - origin).dot(direction);
  const double near_t = (result->single.near_end - origin).dot(direction);
  const double up = far_t < near_t ? -1.0 : 1.0;     // Sign of t toward the far end.
  std::vector<std::pair<double, double>> crossings;  // (t, weight)
  double total = 0;
  for (const MergedLine& other : lines) {
    if (&other == &m || other.length < 0.5 * options.min_length_fraction * height) continue;
    const Eigen::Vector3d x = l.cross(other.line);
    if (std::abs(x.z()) < 1e-9) continue;
    const Eigen::Vector2d p = x.head<2>() / x.z();
    const double t = (p - origin).dot(direction);
    if ((t - far_t) * up < -2.0) continue;  // Crosses on the support: not a vanishing point.
    if (std::abs(l.head<2>().dot(other.line.head<2>())) > std::cos(5.0 * M_PI / 180)) continue;
    crossings.emplace_back(t, other.length);
    total += other.length;
  }
  if (crossings.size() < 2) return;
  std::sort(crossings.begin(), crossings.end());
  double running = 0, median = crossings.front().first;
  for (const auto& [t, w] : crossings) {
    running += w;
    median = t;
    if (running >= 0.5 * total) break;
  }
  // Most votes must agree (within 3% of the image height along the line).
  int votes = 0;
  for (const auto& [t, w] : crossings) votes += std::abs(t - median) < 0.03 * height;
  if (votes < 2 || votes * 2 < static_cast<int>(crossings.size())) return;
  result->single_vp = origin + median * direction;
  result->single_has_vp = true;
  result->single_vp_votes = votes;
}

Status NoCorridor(JunctionPair* result, const std::string& why) {
  result->status = Status::NoCorridorFound(why);
  return Status::Ok();
}

}  // namespace

std::vector<Eigen::Vector2d> FloorSidePixels(const std::vector<Eigen::Vector2d>& edges,
                                             const Eigen::Vector2d& vp, bool left) {
  std::vector<Eigen::Vector2d> side;
  KeepWhere(
      edges, [&](const Eigen::Vector2d& p) {
        const bool beyond = left ? p.x() > vp.x() : p.x() < vp.x();
        return !beyond & !(p.y() < vp.y());
      },
      &side);
  return side;
}

bool JunctionDetectorOptions::Check(std::string* why) const {
  std::string reason;
  if (!(roi_top_fraction >= 0 && roi_top_fraction < 0.95)) {
    reason = "roi_top_fraction must be in [0, 0.95)";
  } else if (!(blur_sigma >= 0 && blur_sigma <= 10)) {
    reason = "blur_sigma must be in [0, 10]";
  } else if (!(canny_high >= 0 && canny_low_ratio > 0 && canny_low_ratio <= 1)) {
    reason = "Canny thresholds: canny_high >= 0 (0 = automatic), canny_low_ratio in (0, 1]";
  } else if (!(canny_auto_percentile > 0 && canny_auto_percentile < 100 && canny_auto_min > 0)) {
    reason = "automatic Canny: percentile in (0, 100) and a positive minimum";
  } else if (hough_threshold < 1) {
    reason = "hough_threshold must be >= 1";
  } else if (!(hough_min_length_fraction > 0 && hough_min_length_fraction < 1)) {
    reason = "hough_min_length_fraction must be in (0, 1)";
  } else if (relaxed_hough_threshold < 0 ||
             !(relaxed_hough_min_length_fraction > 0 && relaxed_hough_min_length_fraction < 1) ||
             !(relaxed_min_line_fraction >= 0 && relaxed_min_line_fraction < 1) ||
             !(relaxed_min_partner_boundary >= 0 && relaxed_min_partner_boundary <= 1)) {
    reason =
        "relaxed_hough_threshold must be >= 0 (0 = no second look), "
        "relaxed_hough_min_length_fraction in (0, 1), relaxed_min_line_fraction in [0, 1) "
        "and relaxed_min_partner_boundary in [0, 1]";
  } else if (!(hough_max_gap >= 0)) {
    reason = "hough_max_gap must be >= 0";
  } else if (!(hough_angle_window_deg >= 0 && hough_angle_window_deg < 90)) {
    reason = "hough_angle_window_deg must be in [0, 90) (0 = all angles, cv::HoughLinesP)";
  } else if (!(merge_angle_deg > 0 && merge_angle_deg < 45 && merge_distance_px > 0)) {
    reason = "merge tolerances must be positive (angle < 45 deg)";
  } else if (!(min_length_fraction >= 0 && max_length_fraction >= 0)) {
    reason = "length bounds must be >= 0";
  } else if (!(min_inclination_deg >= 0 && min_inclination_deg < 90 &&
               max_inclination_deg <= 90)) {
    reason = "inclination bounds must lie in [0, 90] degrees";
  } else if (!(support_distance_px > 0)) {
    reason = "support_distance_px must be positive";
  } else if (!(baseboard_band_contrast >= 0 && baseboard_band_contrast <= 1e6)) {
    reason = "baseboard_band_contrast must be >= 0 (0 = off)";
  } else if (!(max_edge_density > 0 && max_edge_density <= 1)) {
    reason = "max_edge_density must be in (0, 1]";
  } else if (!(max_floor_texture >= 0 && max_floor_texture <= 1) || strong_edge_gradient < 1 ||
             !(floor_line_tolerance_deg >= 0 && floor_line_tolerance_deg < 45)) {
    reason =
        "max_floor_texture must be in [0, 1] (0 = no check), strong_edge_gradient >= 1, "
        "floor_line_tolerance_deg in [0, 45)";
  } else if (max_work_width != 0 && max_work_width < 2 * kMinImageSide) {
    reason = "max_work_width must be 0 (full resolution) or at least " +
             std::to_string(2 * kMinImageSide) + " px";
  }
  if (reason.empty()) return true;
  if (why != nullptr) *why = reason;
  return false;
}

SegmentOptions JunctionSegmentOptions(const JunctionDetectorOptions& options, int height,
                                      int scale) {
  return {options.blur_sigma,
          options.canny_high,
          options.canny_low_ratio,
          options.canny_auto_percentile,
          options.canny_auto_min,
          options.hough_threshold,
          std::max(8.0, options.hough_min_length_fraction * height / scale),
          options.hough_max_gap,
          options.hough_angle_window_deg};
}

std::vector<Eigen::Vector2d> SampleAlongLine(const JunctionLine& line, int n) {
  std::vector<Eigen::Vector2d> points;
  if (n <= 0) return points;
  if (n == 1) return {line.near_end};
  for (int i = 0; i < n; ++i) {
    points.push_back(line.near_end + (line.far_end - line.near_end) * (i / (n - 1.0)));
  }
  return points;
}

namespace {

Status DetectJunctionsIn(const cv::Mat& bgr, const cv::Mat* halved,
                         const JunctionDetectorOptions& options, JunctionPair* result) {
  *result = JunctionPair();
  if (bgr.empty()) return Status::InvalidArgument("image is empty");
  if (bgr.depth() != CV_8U) return Status::InvalidArgument("image must be 8-bit");
  std::string why;
  if (!options.Check(&why)) return Status::InvalidArgument("junction detector: " + why);
  const int width = bgr.cols, height = bgr.rows;
  if (width < kMinImageSide || height < kMinImageSide) {
    std::ostringstream msg;
    msg << "image " << width << "x" << height << " is too small to show a corridor";
    return NoCorridor(result, msg.str());
  }
  cv::Mat color;
  if (bgr.channels() == 1) {
    cv::cvtColor(bgr, color, cv::COLOR_GRAY2BGR);
  } else if (bgr.channels() == 4) {
    cv::cvtColor(bgr, color, cv::COLOR_BGRA2BGR);
  } else if (bgr.channels() == 3) {
    color = bgr;
  } else {
    return Status::InvalidArgument("image must have 1, 3 or 4 channels");
  }
  const int roi_top =
      std::clamp(static_cast<int>(options.roi_top_fraction * height), 0, height - kMinImageSide / 2);
  // Edges and segments at the working resolution: the image halved until it fits
  // max_work_width. cv::pyrDown's 5-tap kernel is centred on every second pixel, so pixel i of an
  // image halved to 1/scale lies at full-image pixel scale * i (an impulse at pixel 2k comes out
  // centred on k). Only the search region is halved, from crop_top (a multiple of scale, a few
  // working rows above it for the kernel): working row j lies at image row crop_top + scale * j.
  // A caller's halved image is the whole image: crop_top 0, and the same search region rows.
  const int scale = WorkingScale(width, options.max_work_width);
  int crop_top = scale == 1 ? 0 : std::max(0, roi_top - 4 * scale) / scale * scale;
  cv::Mat work = color.rowRange(crop_top, height);
  if (halved != nullptr && scale > 1) {
    cv::Size size(width, height);
    for (int s = 1; s < scale; s *= 2) size = cv::Size((size.width + 1) / 2, (size.height + 1) / 2);
    if (halved->size() != size || halved->type() != CV_8UC3) {
      return Status::InvalidArgument(
          "junction detector: the halved image is not the image's "
          "pyrDown to max_work_width");
    }
    crop_top = 0;
    work = *halved;
  } else {
    for (int s = 1; s < scale; s *= 2) PyrDown(work, &work);
  }
  const int work_roi_top = roi_top / scale - crop_top / scale;
  const SegmentOptions segment_options = JunctionSegmentOptions(options, height, scale);
  EdgeSegments found = DetectSegments(work, work_roi_top, segment_options);
  // Working-image segments into full-image coordinates.
  const auto to_image = [&](std::vector<cv::Vec4f>* segments) {
    for (cv::Vec4f& segment : *segments) {
      for (int k = 0; k < 4; ++k) {
        segment[k] = static_cast<float>(scale * segment[k] + (k % 2 == 1 ? crop_top : 0));
      }
    }
  };
  to_image(&found.segments);
  // Edge pixels in full-image coordinates, for the refits, in row-major order.
  const auto edge_points = [&]() {
    std::vector<Eigen::Vector2d> points;
    points.reserve(static_cast<size_t>(cv::countNonZero(found.edges)));
    ForEachEdgePixel(found.edges, [&](int u, int v) {
      points.emplace_back(scale * u, scale * (v + work_roi_top) + crop_top);
    });
    return points;
  };
  const double edge_density =
      cv::countNonZero(found.edges) / static_cast<double>(std::max<size_t>(1, found.edges.total()));
  if (edge_density > options.max_edge_density) {
    std::ostringstream msg;
    msg << "image is noise or texture: " << static_cast<int>(100 * edge_density)
        << "% of the search region are edges";
    return NoCorridor(result, msg.str());
  }
  result->segments = found.segments;

  // The paper's scene prior (eq. 2), read with theta measured from the vertical image axis:
  // lines steeper than 90 deg - atan(H/W) are door frames and pillars, not junctions.
  const double diagonal = std::hypot(width, height);
  const double min_length = options.min_length_fraction * height;
  const double max_length = options.max_length_fraction > 0 ? options.max_length_fraction * diagonal
                                                            : 1e300;
  const double max_inclination = options.max_inclination_deg >= 0
                                     ? options.max_inclination_deg
                                     : 90.0 - std::atan2(height, width) * 180.0 / M_PI;
  FullResolutionRefit refit;
  refit.on = scale > 1 && options.refit_full_resolution;
  refit.bgr = &color;
  refit.options.reach_px = 2.0 * scale;
  refit.options.step_px = scale;  // As many points as the halved image has rows.
  refit.options.threshold = options.canny_low_ratio * found.canny_high;
  refit.options.support_distance_px = options.support_distance_px;
  const cv::Mat roi = color.rowRange(roi_top, height);
  const FloorAppearance floor = SampleFloor(roi, roi_top, 2 * scale);
  BaseboardBandTest band;
  if (options.baseboard_band_contrast > 0) {
    band.min_contrast = options.baseboard_band_contrast;
    band.contrast = [&](const MergedLine& upper, const MergedLine& lower) {
      return BandContrast(roi, floor, upper, lower, roi_top, scale);
    };
  }
  // The lines that may be junctions, per side, and the best pair of them (none when a side has no
  // candidate).
  struct PairSearch {
    std::vector<MergedLine> lines;
    std::vector<JunctionCandidate> left, right;
    SelectedPair pair;
  };
  const auto add_candidates = [&](const std::vector<MergedLine>& lines, double shortest,
                                  PairSearch* out) {
    for (const auto& line : lines) {
      if (line.length < shortest || line.length > max_length) continue;
      if (line.inclination_deg < options.min_inclination_deg ||
          line.inclination_deg > max_inclination) {
        continue;
      }
      JunctionCandidate candidate{line, BoundaryScore(roi, floor, line, roi_top, scale)};
      (line.slope < 0 ? out->left : out->right).push_back(candidate);
    }
  };
  const auto select = [&](PairSearch* out) {
    if (out->left.empty() || out->right.empty()) return;
    out->pair =
        SelectJunctionPair(out->left, out->right, out->lines, Eigen::Vector2d(width, height), band);
  };
  PairSearch chosen;
  chosen.lines = MergeSegments(found.segments, options.merge_angle_deg, options.merge_distance_px);
  add_candidates(chosen.lines, min_length, &chosen);
  select(&chosen);
  if (chosen.pair.left < 0 && options.relaxed_hough_threshold > 0) {
    // A second look at the same edges for shorter pieces: a faint junction broken by door bottoms
    // gives pieces too short for the first Hough, which merge into one line. Only to complete a
    // pair around a first-look line that looks like the floor's edge, with a long line: blob
    // outlines of outdoor scenes give short straight pieces that line up by chance too.
    SegmentOptions relaxed = segment_options;
    relaxed.hough_threshold = options.relaxed_hough_threshold;
    relaxed.hough_min_length =
        std::max(8.0, options.relaxed_hough_min_length_fraction * height / scale);
    std::vector<cv::Vec4f> segments = HoughSegments(found, relaxed);
    to_image(&segments);
    PairSearch second;
    second.lines = MergeSegments(segments, options.merge_angle_deg, options.merge_distance_px);
    add_candidates(second.lines, std::max(min_length, options.relaxed_min_line_fraction * height),
                   &second);
    // The second look's lines first, then the first look's: an index below these counts is new.
    const int new_left = static_cast<int>(second.left.size());
    const int new_right = static_cast<int>(second.right.size());
    second.left.insert(second.left.end(), chosen.left.begin(), chosen.left.end());
    second.right.insert(second.right.end(), chosen.right.begin(), chosen.right.end());
    select(&second);
    const SelectedPair& p = second.pair;
    const bool left_new = p.left < new_left, right_new = p.right < new_right;
    if (p.left >= 0 && left_new != right_new &&
        (left_new ? second.right[p.right] : second.left[p.left]).boundary >=
            options.relaxed_min_partner_boundary) {
      chosen = std::move(second);
      result->segments = std::move(segments);
      result->relaxed_hough = true;
    }
  }
  const std::vector<MergedLine>& lines = chosen.lines;
  const std::vector<JunctionCandidate>& left = chosen.left;
  const std::vector<JunctionCandidate>& right = chosen.right;
  const SelectedPair& pair = chosen.pair;
  if (left.empty() || right.empty()) {
    std::ostringstream msg;
    msg << "no " << (left.empty() ? "left" : "right") << " junction candidate among "
        << lines.size() << " lines";
    const Status status = NoCorridor(result, msg.str());
    if (!left.empty() || !right.empty()) {
      KeepSingleJunction(left.empty() ? right : left, left.empty() ? false : true, lines,
                         edge_points(), options, height, refit, result);
    }
    return status;
  }
  if (pair.left < 0) {
    return NoCorridor(result, "no pair of lines meets at a vanishing point above the floor");
  }
  const std::vector<Eigen::Vector2d> edges = edge_points();
  const double distance = options.support_distance_px;
  result->left = Refine(left[pair.left], edges, pair.vanishing_point, true, distance, height);
  result->right = Refine(right[pair.right], edges, pair.vanishing_point, false, distance, height);
  if (pair.left_lower >= 0) {
    result->left_lower =
        Refine(left[pair.left_lower], edges, pair.vanishing_point, true, distance, height);
    result->has_left_lower = true;
  }
  if (pair.right_lower >= 0) {
    result->right_lower =
        Refine(right[pair.right_lower], edges, pair.vanishing_point, false, distance, height);
    result->has_right_lower = true;
  }
  for (JunctionLine* line : {&result->left, &result->right}) refit.Apply(line);
  if (result->has_left_lower) refit.Apply(&result->left_lower);
  if (result->has_right_lower) refit.Apply(&result->right_lower);
  const Eigen::Vector3d vp = result->left.line.cross(result->right.line);
  result->vanishing_point =
      std::abs(vp.z()) > 1e-12 ? Eigen::Vector2d(vp.head<2>() / vp.z()) : pair.vanishing_point;
  if (options.max_floor_texture > 0) {
    const GradientGrid grid{scale, crop_top + scale * work_roi_top};
    FloorTextureOptions texture_options;
    texture_options.margin = 3.0 * scale;  // Clear of the junctions' own edges (the 5x5 reach).
    texture_options.strong = options.strong_edge_gradient;
    texture_options.line_tolerance_deg = options.floor_line_tolerance_deg;
    const FloorTexture floor_texture =
        MeasureFloorTexture(found.dx, found.dy, grid, result->left.line, result->right.line,
                            result->vanishing_point, texture_options);
    if (floor_texture.floor_pixels >= kMinFloorPixels) {
      result->floor_texture = floor_texture.odd_fraction;
    }
    if (result->floor_texture > options.max_floor_texture) {
      std::ostringstream msg;
      msg.precision(2);
      msg << "the floor between the junction lines is textured: "
          << 100 * floor_texture.odd_fraction
          << "% of it are strong edges along no corridor line (a corridor floor has at most "
          << 100 * options.max_floor_texture << "%); not a corridor";
      return NoCorridor(result, msg.str());
    }
  }
  result->status = Status::Ok();
  return Status::Ok();
}

}  // namespace

Status DetectJunctions(const cv::Mat& bgr, const JunctionDetectorOptions& options,
                       JunctionPair* result) {
  return DetectJunctionsIn(bgr, nullptr, options, result);
}

Status DetectJunctions(const cv::Mat& bgr, const cv::Mat& halved,
                       const JunctionDetectorOptions& options, JunctionPair* result) {
  return DetectJunctionsIn(bgr, &halved, options, result);
}

}  // namespace corridor
