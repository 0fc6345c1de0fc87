#include "perception/junction_detector.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>
#include <vector>

#include <Eigen/Geometry>
#include <opencv2/imgproc.hpp>

#include "perception/appearance.h"
#include "perception/floor_band.h"
#include "perception/floor_lights.h"
#include "perception/floor_texture.h"
#include "perception/junction_candidates.h"
#include "perception/junction_memory.h"
#include "perception/junction_refit.h"
#include "perception/junction_search_region.h"
#include "perception/junction_selector.h"
#include "perception/junction_support.h"
#include "perception/line_ridge.h"
#include "perception/line_segments.h"
#include "perception/lower_edge.h"
#include "perception/reflected_band.h"
#include "perception/single_junction.h"

namespace corridor {
namespace {

constexpr int kMinImageSide = 24;      // Smaller images cannot show a corridor.
constexpr long kMinFloorPixels = 200;  // Fewer floor pixels (working resolution) are too few to judge its texture.

}  // namespace

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
  } else if (floor_band_min_across < 0) {
    reason = "floor_band_min_across must be >= 0 (0 = off)";
  } else if (!(floor_band_texture_density >= 0 && floor_band_texture_density <= 1)) {
    reason = "floor_band_texture_density must be in [0, 1] (0 = off)";
  } else if (!(stripe_floor_likeness >= 0 && stripe_floor_likeness <= 1)) {
    reason = "stripe_floor_likeness must be in [0, 1] (0 = off)";
  } else if (!(inside_floor_likeness >= 0 && inside_floor_likeness <= 1)) {
    reason = "inside_floor_likeness must be in [0, 1] (0 = off)";
  } else if (!(inside_floor_ridge_likeness >= 0 && inside_floor_ridge_likeness <= 1)) {
    reason = "inside_floor_ridge_likeness must be in [0, 1] (0 = off)";
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

namespace {

Status NoCorridor(JunctionPair* result, const std::string& why) {
  result->status = Status::NoCorridorFound(why);
  return Status::Ok();
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

// The refit of the chosen lines on the full-resolution `color`, when the search ran at 1/scale
// of it: edge points within two working pixels, one per working row, at Canny's low threshold.
FullResolutionRefit MakeFullResolutionRefit(const cv::Mat& color, int scale,
                                            const JunctionDetectorOptions& options,
                                            double canny_high) {
  FullResolutionRefit refit;
  refit.on = scale > 1 && options.refit_full_resolution;
  refit.bgr = &color;
  refit.options.reach_px = 2.0 * scale;
  refit.options.step_px = scale;  // As many points as the halved image has rows.
  refit.options.threshold = options.canny_low_ratio * canny_high;
  refit.options.support_distance_px = options.support_distance_px;
  return refit;
}

// The fraction of the search region that is edges: noise and texture have many.
double EdgeDensity(const cv::Mat& edges) {
  return cv::countNonZero(edges) / static_cast<double>(std::max<size_t>(1, edges.total()));
}

// The baseboard rule's band test on the floor `cues`, and its search for a band's lower edge
// where no line was found for it (none when baseboard_band_contrast is 0).
// The test refers to `cues`, which must outlive it.
BaseboardBandTest MakeBandTest(const JunctionDetectorOptions& options, const FloorCues& cues) {
  BaseboardBandTest band;
  if (options.baseboard_band_contrast > 0) {
    band.min_contrast = options.baseboard_band_contrast;
    band.contrast = [&cues](const MergedLine& upper, const MergedLine& lower) {
      return BandContrast(cues.roi, cues.floor, upper, lower, cues.roi_top, cues.scale);
    };
    band.lower_edge = [&cues](const MergedLine& chosen, const Eigen::Vector2d& vp, bool left,
                              double max_angle_deg, JunctionCandidate* foot) {
      return FindLowerEdge(cues.roi, cues.roi_top, chosen, vp, left, max_angle_deg, &foot->line,
                           &foot->foot_turn_deg);
    };
    band.boundary = [&cues](const MergedLine& line) {
      return BoundaryScore(cues.roi, cues.floor, line, cues.roi_top, cues.scale);
    };
  }
  return band;
}

// The one visible junction when only one side has candidates (OutermostFloorEdge), refined on
// the edge pixels below its top end and refitted, and where the other lines meet it.
void KeepSingleJunction(const std::vector<JunctionCandidate>& side, bool is_left,
                        const std::vector<MergedLine>& lines,
                        const std::vector<Eigen::Vector2d>& edges,
                        const JunctionDetectorOptions& options, int height,
                        const FullResolutionRefit& refit, JunctionPair* result) {
  const int best = OutermostFloorEdge(side, is_left, height);
  if (best < 0) return;  // No line looks like the floor's edge.
  const MergedLine& m = side[best].line;
  const Eigen::Vector2d top = m.start.y() < m.end.y() ? m.start : m.end;
  result->single = RefineJunction(side[best], edges, top, is_left, options.support_distance_px,
                                  height);
  refit.Apply(&result->single);
  result->single_is_left = is_left;
  result->has_single = true;
  result->single_has_vp =
      VoteSingleVanishingPoint(result->single, m, lines, 0.5 * options.min_length_fraction * height,
                               height, &result->single_vp, &result->single_vp_votes);
}

// Stage: what no search can use (an empty or non-8-bit image, bad options): InvalidArgument.
Status CheckInput(const cv::Mat& bgr, const JunctionDetectorOptions& options) {
  if (bgr.empty()) return Status::InvalidArgument("image is empty");
  if (bgr.depth() != CV_8U) return Status::InvalidArgument("image must be 8-bit");
  std::string why;
  if (!options.Check(&why)) return Status::InvalidArgument("junction detector: " + why);
  return Status::Ok();
}

// Stage: an image too small to show a corridor; true with the reason in *why.
bool TooSmall(const cv::Mat& bgr, std::string* why) {
  if (bgr.cols >= kMinImageSide && bgr.rows >= kMinImageSide) return false;
  std::ostringstream msg;
  msg << "image " << bgr.cols << "x" << bgr.rows << " is too small to show a corridor";
  *why = msg.str();
  return true;
}

// Stage: the input as 8-bit BGR (grey and BGRA converted; BGR shared, not copied).
Status ToColor(const cv::Mat& bgr, cv::Mat* color) {
  if (bgr.channels() == 1) {
    cv::cvtColor(bgr, *color, cv::COLOR_GRAY2BGR);
  } else if (bgr.channels() == 4) {
    cv::cvtColor(bgr, *color, cv::COLOR_BGRA2BGR);
  } else if (bgr.channels() == 3) {
    *color = bgr;
  } else {
    return Status::InvalidArgument("image must have 1, 3 or 4 channels");
  }
  return Status::Ok();
}

// The first image row of the search region: roi_top_fraction of the height, leaving at least
// half the smallest image side below it.
int SearchTop(const JunctionDetectorOptions& options, int height) {
  return std::clamp(static_cast<int>(options.roi_top_fraction * height), 0,
                    height - kMinImageSide / 2);
}

// Stage: Canny edges and Hough segments of the search region into *found (which keeps its
// memory); the segments in image pixels.
void FindEdgeSegments(const JunctionSearchRegion& region, const SegmentOptions& options,
                      EdgeSegments* found) {
  DetectSegments(region.work, region.work_roi_top, options, found);
  SegmentsToImage(region, &found->segments);
}

// Stage: more edges than max_edge_density of the search region are noise or texture, not a
// corridor; true with the reason in *why.
bool NoiseOrTexture(const cv::Mat& edges, const JunctionDetectorOptions& options,
                    std::string* why) {
  const double edge_density = EdgeDensity(edges);
  if (!(edge_density > options.max_edge_density)) return false;
  std::ostringstream msg;
  msg << "image is noise or texture: " << static_cast<int>(100 * edge_density)
      << "% of the search region are edges";
  *why = msg.str();
  return true;
}

// Stage: the candidates (scene prior, boundary scores against the floor's appearance) and the
// best pair, into *chosen: the first look, then the second when it finds none (which, when taken,
// replaces result->segments and sets result->relaxed_hough).
void SearchPair(const cv::Mat& color, const JunctionSearchRegion& region,
                const EdgeSegments& found, const SegmentOptions& segment_options,
                const JunctionDetectorOptions& options, JunctionPair* result, PairSearch* chosen) {
  const int width = color.cols, height = color.rows;
  const JunctionScenePrior prior = MakeJunctionScenePrior(options, width, height);
  FloorCues cues;
  cues.roi = color.rowRange(region.roi_top, height);
  cues.floor = SampleFloor(cues.roi, region.roi_top, 2 * region.scale);
  cues.roi_top = region.roi_top;
  cues.scale = region.scale;
  const BaseboardBandTest band = MakeBandTest(options, cues);
  cues.floor_band.min_across = options.floor_band_min_across;
  cues.floor_band.min_texture_density = options.floor_band_texture_density;
  // The ridge's relaxation is part of the inside-floor rule: it never runs without it.
  const bool floor_colour_rules =
      options.stripe_floor_likeness > 0 || options.inside_floor_likeness > 0;
  // What the band measure reads, referred to by one pointer (a capture std::function keeps
  // without allocating).
  struct BandMeasure {
    const EdgeSegments* found;
    GradientGrid grid;
    BandEdgeOptions options;
  };
  BandMeasure band_measure{&found, SearchRegionGrid(region), BandEdgeOptions()};
  if (options.floor_band_min_across > 0 || floor_colour_rules) {
    // Clear of the lines' own edges (the 5x5 reach).
    band_measure.options.margin = 3.0 * region.scale;
    cues.floor_band.measure = [m = &band_measure](const MergedLine& inner,
                                                  const MergedLine& outer,
                                                  const Eigen::Vector2d& vp) {
      return MeasureBandEdges(m->found->edges, m->found->dx, m->found->dy, m->grid, inner.line,
                              outer.line, vp, m->options);
    };
    cues.floor_band.boundary = [&cues](const MergedLine& outer) {
      return BoundaryScore(cues.roi, SampleBelowLine(cues.roi, outer, cues.roi_top, cues.scale),
                           outer, cues.roi_top, cues.scale);
    };
  }
  if (floor_colour_rules) {
    cues.floor_band.stripe_min_beyond = options.stripe_floor_likeness;
    cues.floor_band.inside_min_likeness = options.inside_floor_likeness;
    cues.floor_band.floor_below = [&cues](const MergedLine& line) {
      return SampleBelowLine(cues.roi, line, cues.roi_top, cues.scale);
    };
    cues.floor_band.floor_above = [&cues](const FloorAppearance& floor, const MergedLine& line) {
      return FloorLikenessAbove(cues.roi, floor, line, cues.roi_top, cues.scale);
    };
    cues.floor_band.ridge = [&cues](const MergedLine& line) {
      return RidgeFraction(cues.roi, line, cues.roi_top, cues.scale);
    };
    cues.floor_band.ridge_min_likeness = options.inside_floor_ridge_likeness;
    cues.floor_band.ridge_width_px = 4.0 * region.scale;
  }
  const Eigen::Vector2d size(width, height);
  FirstLook(found.segments, options, prior, cues, size, band, chosen);
  if (chosen->pair.left < 0 && options.relaxed_hough_threshold > 0) {
    std::vector<cv::Vec4f> segments;
    if (SecondLook(found, segment_options, region, options, prior, cues, size, band, chosen,
                   &segments)) {
      result->segments = std::move(segments);
      result->relaxed_hough = true;
    }
  }
}

// Stage, when a side has no candidate: the refusal, with the other side's one junction kept
// (KeepSingleJunction) when it has candidates.
Status OneSideOnly(const PairSearch& chosen, const std::vector<Eigen::Vector2d>& edges,
                   const JunctionDetectorOptions& options, int height,
                   const FullResolutionRefit& refit, JunctionPair* result) {
  std::ostringstream msg;
  const char* side = chosen.left.empty() && chosen.right.empty() ? "left or right"
                     : chosen.left.empty()                       ? "left"
                                                                 : "right";
  msg << "no " << side << " junction candidate among " << chosen.lines.size() << " lines";
  const Status status = NoCorridor(result, msg.str());
  if (!chosen.left.empty() || !chosen.right.empty()) {
    const bool is_left = !chosen.left.empty();
    KeepSingleJunction(is_left ? chosen.left : chosen.right, is_left, chosen.lines, edges,
                       options, height, refit, result);
  }
  return status;
}

// Where the pair's two junction lines meet; `otherwise` when they are parallel.
Eigen::Vector2d WhereJunctionsMeet(const JunctionPair& pair, const Eigen::Vector2d& otherwise) {
  const Eigen::Vector3d x = pair.left.line.cross(pair.right.line);
  return std::abs(x.z()) > 1e-12 ? Eigen::Vector2d(x.head<2>() / x.z()) : otherwise;
}

// Stage: the chosen pair's final lines (and the lower partners the baseboard rule left), refined
// on their edge pixels and refitted at full resolution, and their vanishing point.
void RefineChosenPair(const PairSearch& chosen, const std::vector<Eigen::Vector2d>& edges,
                      double distance, int height, const FullResolutionRefit& refit,
                      JunctionPair* result) {
  const std::vector<JunctionCandidate>& left = chosen.left;
  const std::vector<JunctionCandidate>& right = chosen.right;
  const SelectedPair& pair = chosen.pair;
  // A band's lower edge found from colours is refined as the line above it (the band's strong
  // top edge, on which the line search found it), then turned about the refined vanishing point:
  // fitted on edge pixels itself, it would be drawn to that top edge where the band is thin.
  const JunctionCandidate& lc = left[pair.left];
  const JunctionCandidate& rc = right[pair.right];
  result->left = RefineJunction(lc.foot_of >= 0 ? left[lc.foot_of] : lc, edges,
                                pair.vanishing_point, true, distance, height);
  result->right = RefineJunction(rc.foot_of >= 0 ? right[rc.foot_of] : rc, edges,
                                 pair.vanishing_point, false, distance, height);
  if (pair.left_lower >= 0) {
    result->left_lower =
        RefineJunction(left[pair.left_lower], edges, pair.vanishing_point, true, distance, height);
    result->has_left_lower = true;
  }
  if (pair.right_lower >= 0) {
    result->right_lower = RefineJunction(right[pair.right_lower], edges, pair.vanishing_point,
                                         false, distance, height);
    result->has_right_lower = true;
  }
  for (JunctionLine* line : {&result->left, &result->right}) refit.Apply(line);
  if (result->has_left_lower) refit.Apply(&result->left_lower);
  if (result->has_right_lower) refit.Apply(&result->right_lower);
  const Eigen::Vector2d refined = WhereJunctionsMeet(*result, pair.vanishing_point);
  if (lc.foot_of >= 0) TurnJunctionToFoot(lc.line, lc.foot_turn_deg, refined, true, &result->left);
  if (rc.foot_of >= 0) {
    TurnJunctionToFoot(rc.line, rc.foot_turn_deg, refined, false, &result->right);
  }
  result->vanishing_point = WhereJunctionsMeet(*result, pair.vanishing_point);
}

// The largest difference, relative to the reflecting wall's, between the two walls' band heights
// (BandAboveJunction) when both junctions are taken at their reflections' lower edges.
constexpr double kMaxBandHeightDifference = 0.15;
// The least fraction of the floor brighter than the walls for it to mirror the ceiling's lights.
constexpr double kMinMirroredLights = 0.005;
// One wall alone must show its reflection as a near-exact blend of its baseboard and the floor:
// a diffuse floor's baseboard with a darker foot is a blend to within about 5% of its contrast.
constexpr double kMaxOneWallGlossResidual = 0.03;

// When one wall's junction reads as a reflection's lower edge and the other's does not: if that
// reflection is a near-exact blend of its baseboard and the floor and the floor mirrors the
// ceiling's lights (one wall alone is weak evidence: a baseboard with a darker foot, or a real
// glossy floor's uneven reflection, can read so), the other wall's band, of the same height
// relative to the camera's, ends at its reflection's lower edge too (one floor and one
// baseboard), and its junction is taken at the band's middle. `at_middle`: per side, whether its
// junction already stands at its band's middle (JunctionAtReflectedBandsMiddle).
void TakeOtherWallsBandAsReflected(const cv::Mat& color, JunctionLine* const lines[2],
                                   const Eigen::Vector2d& vp, const bool at_middle[2],
                                   bool reflected[2], double turn[2]) {
  const int seen = reflected[0] ? 0 : 1, other = 1 - seen;
  if (at_middle[other]) return;  // Already between its baseboard and its reflection.
  // The seen wall's turn is already in turn[seen]; these are asked only whether and how high.
  double seen_height = 0, other_height = 0, unused_turn = 0, other_turn = 0;
  if (!FindReflectedJunction(color, *lines[seen], vp, seen == 0, 2 * kBaseboardMaxTurnDeg,
                             &unused_turn, kMaxOneWallGlossResidual) ||
      !BandAboveJunction(color, *lines[seen], vp, seen == 0, 2 * kBaseboardMaxTurnDeg,
                         &seen_height, &unused_turn) ||
      !BandAboveJunction(color, *lines[other], vp, other == 0, 2 * kBaseboardMaxTurnDeg,
                         &other_height, &other_turn)) {
    return;
  }
  if (!(seen_height > 0) ||
      std::abs(other_height - seen_height) > kMaxBandHeightDifference * seen_height ||
      !FloorMirrorsLights(color, lines[0]->line, lines[1]->line, vp, kMinMirroredLights)) {
    return;
  }
  reflected[other] = true;
  turn[other] = other_turn;
}

// Stage: on a polished floor, a junction taken at its baseboard's reflection's lower edge moves up
// to the middle of the band, and one taken at the baseboard's top down to it (reflected_band.h),
// and the vanishing point with them.
void TakeJunctionsAboveReflections(const cv::Mat& color, JunctionPair* result) {
  const Eigen::Vector2d vp = result->vanishing_point;
  // One floor mirrors both walls' baseboards: both walls must show a reflection, below the
  // junction (to be moved up to the band's middle) or about it (the junction already there).
  JunctionLine* lines[2] = {&result->left, &result->right};  // Left, right.
  double turn[2] = {0, 0};
  bool reflected[2] = {false, false};
  // Already at a band's middle: asked once of each side not reflected (the lines do not change
  // until the end).
  bool at_middle[2] = {false, false};
  for (int side = 0; side < 2; ++side) {
    reflected[side] = FindReflectedJunction(color, *lines[side], vp, side == 0,
                                            2 * kBaseboardMaxTurnDeg, &turn[side]);
    if (reflected[side]) continue;
    at_middle[side] = JunctionAtReflectedBandsMiddle(color, *lines[side], vp, side == 0,
                                                     2 * kBaseboardMaxTurnDeg);
    // Or taken at the baseboard's top, with the baseboard and its reflection below it.
    if (!at_middle[side]) {
      reflected[side] = FindJunctionBelowBandTop(color, *lines[side], vp, side == 0,
                                                 2 * kBaseboardMaxTurnDeg, &turn[side]);
    }
  }
  if (!reflected[0] && !reflected[1]) {
    // Both already at their bands' middles: nothing to move.
    for (int side = 0; side < 2; ++side) {
      result->at_reflected_band[side] = at_middle[0] && at_middle[1];
    }
    return;
  }
  if (reflected[0] != reflected[1]) {
    TakeOtherWallsBandAsReflected(color, lines, vp, at_middle, reflected, turn);
  }
  for (int side = 0; side < 2; ++side) {
    if (!reflected[side] && !at_middle[side]) return;
  }
  for (int side = 0; side < 2; ++side) {
    result->at_reflected_band[side] = true;
    if (!reflected[side]) continue;
    JunctionLine& line = *lines[side];
    TurnJunctionToFoot(LineThrough(line.near_end, line.far_end), turn[side], vp, side == 0, &line);
  }
  result->vanishing_point = WhereJunctionsMeet(*result, vp);
}

// Stage: the floor between the junctions (result->floor_texture, when enough of it is seen);
// true, with the reason in *why, when it has too many strong edges along no corridor line for a
// corridor floor (an outdoor scene, a still life).
bool FloorIsTextured(const EdgeSegments& found, const JunctionSearchRegion& region,
                     const JunctionDetectorOptions& options, JunctionPair* result,
                     std::string* why) {
  FloorTextureOptions texture_options;
  // Clear of the junctions' own edges (the 5x5 reach).
  texture_options.margin = 3.0 * region.scale;
  texture_options.strong = options.strong_edge_gradient;
  texture_options.line_tolerance_deg = options.floor_line_tolerance_deg;
  const FloorTexture floor_texture =
      MeasureFloorTexture(found.dx, found.dy, SearchRegionGrid(region), result->left.line,
                          result->right.line, result->vanishing_point, texture_options);
  if (floor_texture.floor_pixels >= kMinFloorPixels) {
    result->floor_texture = floor_texture.odd_fraction;
  }
  if (!(result->floor_texture > options.max_floor_texture)) return false;
  std::ostringstream msg;
  msg.precision(2);
  msg << "the floor between the junction lines is textured: " << 100 * floor_texture.odd_fraction
      << "% of it are strong edges along no corridor line (a corridor floor has at most "
      << 100 * options.max_floor_texture << "%); not a corridor";
  *why = msg.str();
  return true;
}

// The junction search, stage by stage; `halved` (may be null) as for the second DetectJunctions.
Status DetectJunctionsIn(const cv::Mat& bgr, const cv::Mat* halved,
                         const JunctionDetectorOptions& options, JunctionPair* result) {
  *result = JunctionPair();
  // The input: usable at all, large enough, as colour.
  Status status = CheckInput(bgr, options);
  if (!status.ok()) return status;
  std::string why;
  if (TooSmall(bgr, &why)) return NoCorridor(result, why);
  cv::Mat color;
  status = ToColor(bgr, &color);
  if (!status.ok()) return status;
  const int height = color.rows;
  // The search region at the working resolution, its edges and segments.
  JunctionSearchRegion region;
  status = MakeJunctionSearchRegion(color, halved, SearchTop(options, height),
                                    options.max_work_width, &region);
  if (!status.ok()) return status;
  const SegmentOptions segment_options = JunctionSegmentOptions(options, height, region.scale);
  // The edges in the thread's buffer, whose matrices keep their memory from frame to frame
  // (nothing holds them past the search); the segments in a spare result's (junction_memory.h),
  // for the result takes them.
  thread_local EdgeSegments thread_found;
  EdgeSegments& found = thread_found;
  if (found.segments.capacity() == 0) found.segments = SpareSegments();
  FindEdgeSegments(region, segment_options, &found);
  if (NoiseOrTexture(found.edges, options, &why)) return NoCorridor(result, why);
  // The candidates and the best pair of them, in the thread's buffer, whose vectors keep their
  // memory from frame to frame.
  thread_local PairSearch thread_chosen;
  SearchPair(color, region, found, segment_options, options, result, &thread_chosen);
  const PairSearch& chosen = thread_chosen;
  // The segments are the result's (moved, not copied: nothing reads them further), unless the
  // second look has put its own there.
  if (!result->relaxed_hough) result->segments = std::move(found.segments);
  const FullResolutionRefit refit =
      MakeFullResolutionRefit(color, region.scale, options, found.canny_high);
  // The edge pixels in image coordinates, in the thread's buffer (it keeps its memory).
  thread_local std::vector<Eigen::Vector2d> thread_edge_pixels;
  std::vector<Eigen::Vector2d>& edge_pixels = thread_edge_pixels;
  if (chosen.left.empty() || chosen.right.empty()) {
    EdgePixelsInImage(region, found.edges, &edge_pixels);
    return OneSideOnly(chosen, edge_pixels, options, height, refit, result);
  }
  if (chosen.pair.left < 0) {
    return NoCorridor(result, "no pair of lines meets at a vanishing point above the floor");
  }
  // The pair's final lines; the floor between them must look like a corridor's.
  EdgePixelsInImage(region, found.edges, &edge_pixels);
  RefineChosenPair(chosen, edge_pixels, options.support_distance_px,
                   height, refit, result);
  TakeJunctionsAboveReflections(color, result);
  if (options.max_floor_texture > 0 && FloorIsTextured(found, region, options, result, &why)) {
    return NoCorridor(result, why);
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
