#include "pipeline/recover_depth.h"

#include <chrono>
#include <cmath>
#include <iomanip>
#include <limits>
#include <mutex>
#include <sstream>

#include <Eigen/Geometry>
#include <opencv2/imgproc.hpp>

#include "estimation/corridor_observation.h"
#include "estimation/junction_line_residual.h"
#include "pipeline/one_junction.h"

namespace corridor {
namespace {

using Clock = std::chrono::steady_clock;

// OpenCV 4.6 builds its BGR->Lab tables lazily and without a lock (color_lab.cpp, initLabTabs):
// two threads converting their first image at once both build them, and one copy leaks (found by
// LeakSanitizer in corridor_eval --threads=2). Building them once, before any Recover, keeps
// concurrent Recover calls clean. (Perception converts to Lab: the junction detector's floor
// appearance.)
void BuildOpenCvTablesOnce() {
  static std::once_flag once;
  std::call_once(once, [] {
    cv::Mat lab;
    cv::cvtColor(cv::Mat(1, 1, CV_8UC3, cv::Scalar::all(128)), lab, cv::COLOR_BGR2Lab);
  });
}

// The rasterisers write 0 where they have no estimate; the pipeline's depth says so with NaN,
// which depth_image_proc and point-cloud code read as no point (0 would be a point at the origin).
void MarkNoEstimateNaN(cv::Mat* depth) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (int v = 0; v < depth->rows; ++v) {
    float* row = depth->ptr<float>(v);
    for (int u = 0; u < depth->cols; ++u) row[u] = row[u] > 0 ? row[u] : nan;
  }
}

double SecondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// 8-bit BGR view of the input, or an error naming what is wrong with it.
Status ToBgr(const cv::Mat& image, const Camera& camera, cv::Mat* bgr) {
  if (image.empty()) return Status::InvalidArgument("image is empty");
  if (image.cols != camera.image_width || image.rows != camera.image_height) {
    std::ostringstream msg;
    msg << "image is " << image.cols << "x" << image.rows << " but the calibration is for "
        << camera.image_width << "x" << camera.image_height;
    return Status::InvalidArgument(msg.str());
  }
  cv::Mat eight_bit = image;
  if (image.depth() == CV_16U) {
    image.convertTo(eight_bit, CV_8U, 1.0 / 257.0);  // 65535 -> 255, as ReadColorImage does.
  } else if (image.depth() != CV_8U) {
    return Status::InvalidArgument("image must be 8- or 16-bit unsigned, but it is " +
                                   cv::typeToString(image.type()));
  }
  if (eight_bit.channels() == 3) {
    *bgr = eight_bit;
  } else if (eight_bit.channels() == 1) {
    cv::cvtColor(eight_bit, *bgr, cv::COLOR_GRAY2BGR);
  } else if (eight_bit.channels() == 2) {  // Grey + alpha: keep the grey.
    cv::Mat grey;
    cv::extractChannel(eight_bit, grey, 0);
    cv::cvtColor(grey, *bgr, cv::COLOR_GRAY2BGR);
  } else if (eight_bit.channels() == 4) {
    cv::cvtColor(eight_bit, *bgr, cv::COLOR_BGRA2BGR);
  } else {
    return Status::InvalidArgument("image must have 1, 2, 3 or 4 channels, but it has " +
                                   std::to_string(eight_bit.channels()));
  }
  return Status::Ok();
}

// Points along a junction line, in ideal (undistorted) pixels.
std::vector<Eigen::Vector2d> IdealSamples(const JunctionLine& line, int n, const Camera& camera) {
  std::vector<Eigen::Vector2d> points = SampleAlongLine(line, n);
  for (auto& p : points) p = camera.Undistort(p);
  return points;
}

}  // namespace

CorridorObservation ObservationFromJunctions(const JunctionPair& junctions, const Camera& camera,
                                             int points_per_line) {
  CorridorObservation observation = CorridorObservation::FromCamera(camera);
  observation.left = IdealSamples(junctions.left, points_per_line, camera);
  observation.right = IdealSamples(junctions.right, points_per_line, camera);
  return observation;
}

bool RecoverDepthOptions::Check(std::string* why) const {
  std::string reason;
  if (points_per_line < 3 || points_per_line > 10000) {
    reason = "points_per_line must be in [3, 10000]";
  } else if (!(min_width > 0 && min_width < max_width && std::isfinite(max_width))) {
    reason = "width bounds must satisfy 0 < min_width < max_width";
  } else if (!(max_abs_yaw > 0 && max_abs_yaw < M_PI / 2)) {
    reason = "max_abs_yaw must be in (0, pi/2)";
  } else if (!(max_abs_pitch > 0 && max_abs_pitch < M_PI / 2)) {
    reason = "max_abs_pitch must be in (0, pi/2)";
  } else if (!(max_line_error > 0 && std::isfinite(max_line_error))) {
    reason = "max_line_error must be positive and finite";
  } else if (!(width_prior >= 0 && std::isfinite(width_prior))) {
    reason = "width_prior must be >= 0 (0 = none)";
  } else if (!(max_width_change >= 0 && max_width_change < 1)) {
    reason = "max_width_change must be in [0, 1) (0 = off)";
  } else if (!(max_ceiling_disagreement >= 0 && std::isfinite(max_ceiling_disagreement))) {
    reason = "max_ceiling_disagreement must be finite and >= 0 (0 = off)";
  } else if (!(max_ceiling_change >= 0 && max_ceiling_change < 1)) {
    reason = "max_ceiling_change must be in [0, 1) (0 = off)";
  } else if (!(ceiling_height >= 0 && std::isfinite(ceiling_height))) {
    reason = "ceiling_height must be >= 0 (0 = unknown)";
  } else if (!(min_confidence >= 0 && min_confidence <= 1)) {
    reason = "min_confidence must be in [0, 1] (0 = never refuse on confidence)";
  } else if (search_max_width != 0 && search_max_width < 64) {
    reason = "search_max_width must be 0 (full resolution) or at least 64 px";
  } else if (!perception.Check(&reason)) {
    reason = "perception: " + reason;
  } else if (!tracker.Check(&reason)) {
    reason = "tracker: " + reason;
  } else if (!ceiling.Check(&reason)) {
    reason = "ceiling: " + reason;
  } else if (!end_wall.Check(&reason)) {
    reason = "end_wall: " + reason;
  } else if (!inner_line.Check(&reason)) {
    reason = "inner_line: " + reason;
  } else if (!vertical_crossings.Check(&reason)) {
    reason = "vertical_crossings: " + reason;
  }
  if (reason.empty()) return true;
  if (why != nullptr) *why = reason;
  return false;
}

namespace {

// Two ceiling sides, each searched alone, whose heights above the camera are within this ratio
// agree: their walls need no check (CheckBaseboards), and confirm a narrower width (the hold).
constexpr double kSidesAgree = 1.06;

// Adds how the geometry came about to result->fallback ("; " between notes).
void AddFallbackNote(const std::string& how, RecoverDepthResult* result) {
  result->fallback += (result->fallback.empty() ? "" : "; ") + how;
}

// In a sequence, a width much narrower than the previous frame's (max_change) means that one
// junction is wrong (a box edge or a grout line taken for it). Only a narrower width: the lines
// mistaken for a junction lie inside the floor, while a wider width is as often the correction of
// an earlier mistake.
bool MuchNarrower(const CorridorGeometry& previous, double max_change, const CorridorGeometry& g) {
  return max_change > 0 && previous.width > 0 && g.width < (1 - max_change) * previous.width;
}

// Holds such a width: the wall that moved less since the previous frame stays, and the other one
// is put at the previous width from it.
void HoldWidth(const CorridorGeometry& previous, double max_change, CorridorGeometry* g,
               RecoverDepthResult* result) {
  if (!MuchNarrower(previous, max_change, *g)) return;
  const bool keep_left = std::abs(g->LeftDistance() - previous.LeftDistance()) <=
                         std::abs(g->RightDistance() - previous.RightDistance());
  const double kept = keep_left ? g->LeftDistance() : g->RightDistance();
  const double other = previous.width - kept;
  if (!(other > 0.05)) return;  // The kept wall is beyond the previous width: nothing to hold.
  std::ostringstream how;
  how.precision(2);
  how << std::fixed << "width " << g->width << " m is much narrower than the previous frame's "
      << previous.width << " m: the " << (keep_left ? "left" : "right")
      << " wall kept, the previous width held";
  g->offset = keep_left ? kept - 0.5 * previous.width : 0.5 * previous.width - kept;
  g->width = previous.width;
  result->width_held = true;
  AddFallbackNote(how.str(), result);
}

// Both ceiling junctions, each searched alone, with at least min_support: how far apart their
// heights above the camera are, |log(a_l / a_r)|; negative when they cannot be compared.
double CeilingDisagreement(const CeilingEstimate& ceiling, double camera_height,
                           double min_support = 0.45) {
  const double a_left = ceiling.side_height[0] - camera_height;
  const double a_right = ceiling.side_height[1] - camera_height;
  if (!ceiling.found || ceiling.side_support[0] < min_support ||
      ceiling.side_support[1] < min_support || !(a_left > 0.1) || !(a_right > 0.1)) {
    return -1;
  }
  return std::abs(std::log(a_left / a_right));
}

// In a sequence, the ceiling is as constant as the width: a frame whose ceiling is not trusted (not
// found, its two sides too weak to compare, or disagreeing because a wall distance is wrong and
// so its side's height) takes the previous trusted height.
// `previous` carries a ceiling only when one was trusted (SequencePrior).
void HoldCeiling(const CorridorGeometry* previous, double max_disagreement, double min_support,
                 CorridorGeometry* g, RecoverDepthResult* result) {
  const double disagreement = CeilingDisagreement(result->ceiling, g->camera_height, min_support);
  const bool found = result->ceiling.found && g->HasCeiling();
  result->ceiling_trusted = found && disagreement >= 0 && disagreement <= max_disagreement;
  if (!(max_disagreement > 0) || previous == nullptr || !previous->HasCeiling()) return;
  if (result->ceiling_trusted) return;
  const CorridorGeometry& held = *previous;
  std::ostringstream how;
  how.precision(2);
  how << std::fixed;
  if (found && disagreement >= 0) {
    how << "ceiling sides at " << result->ceiling.side_height[0] << " and "
        << result->ceiling.side_height[1] << " m disagree";
  } else {
    how << (found ? "ceiling sides too weak to compare" : "no ceiling found");
  }
  how << ": the previous frame's " << held.ceiling_height << " m held";
  g->ceiling_height = held.ceiling_height;
  result->ceiling_held = true;
  AddFallbackNote(how.str(), result);
}

// In a sequence, a ceiling whose two sides agree (trusted) but whose height above the camera is
// far from the last trusted one's, with the width off by the same factor: both walls were put
// wrong by that factor (lines inside the floor on both sides, as boxes' edges are, put both walls
// too near, and their two ceiling sides, each scaled alike, agree with each other). The corridor's
// ceiling does not change along it, and a corridor that narrows keeps its ceiling: both walls are
// scaled to the trusted ceiling.
void ScaleWallsToCeiling(const CorridorGeometry& previous, double max_change, CorridorGeometry* g,
                         RecoverDepthResult* result) {
  if (!(max_change > 0) || !previous.HasCeiling() || !result->ceiling_trusted ||
      result->width_held || !(previous.width > 0) || !(g->width > 0)) {
    return;
  }
  const double above_previous = previous.ceiling_height - g->camera_height;
  const double above = g->ceiling_height - g->camera_height;
  if (!(above_previous > 0.1) || !(above > 0.1)) return;
  const double factor = above_previous / above;
  const double width_factor = previous.width / g->width;
  if (std::abs(std::log(factor)) <= std::log(1 + max_change) ||
      std::abs(std::log(width_factor / factor)) > std::log(1.15)) {
    return;
  }
  std::ostringstream how;
  how.precision(2);
  how << std::fixed << "both walls scaled " << factor << "x: both ceiling sides at "
      << g->ceiling_height << " m against the previous frame's " << previous.ceiling_height
      << " m (and the width alike): both junctions wrong alike";
  g->SetWallDistances(factor * g->LeftDistance(), factor * g->RightDistance());
  g->ceiling_height = previous.ceiling_height;
  result->walls_scaled = true;
  AddFallbackNote(how.str(), result);
}

}  // namespace

Status CheckPlausible(const CorridorGeometry& g, const RecoverDepthOptions& options) {
  std::ostringstream msg;
  if (!std::isfinite(g.yaw) || !std::isfinite(g.pitch) || !std::isfinite(g.offset) ||
      !std::isfinite(g.width)) {
    msg << "non-finite estimate";
  } else if (g.width < options.min_width || g.width > options.max_width) {
    msg << "width " << g.width << " m is outside [" << options.min_width << ", "
        << options.max_width << "] m";
  } else if (std::abs(g.yaw) > options.max_abs_yaw) {
    msg << "yaw " << g.yaw << " rad is beyond +-" << options.max_abs_yaw << " rad";
  } else if (std::abs(g.pitch) > options.max_abs_pitch) {
    msg << "pitch " << g.pitch << " rad is beyond +-" << options.max_abs_pitch << " rad";
  } else if (g.LeftDistance() <= 0 || g.RightDistance() <= 0) {
    msg << "the camera is not between the walls (offset " << g.offset << " m, width " << g.width
        << " m)";
  } else {
    return Status::Ok();
  }
  return Status::ImplausibleGeometry(msg.str());
}

Status CheckLineFit(const CorridorGeometry& g, const CorridorObservation& observation,
                    const Camera& camera, const RecoverDepthOptions& options) {
  const FloorIntrinsics k{observation.fx, observation.fy, observation.cx, observation.cy,
                          observation.camera_height};
  const double x[JunctionLineResidual::kNumParameters] = {g.yaw, g.pitch, g.offset, g.width};
  double sum = 0;
  int n = 0;
  bool defined = true;
  for (const int side : {-1, 1}) {
    for (const Eigen::Vector2d& p : side < 0 ? observation.left : observation.right) {
      double r = 0;
      defined = defined && JunctionLineResidual(k, p.x(), p.y(), side)(x, &r) && std::isfinite(r);
      sum += r * r;
      ++n;
    }
  }
  const double rms = n > 0 ? std::sqrt(sum / n) : 0.0;
  const double limit = options.max_line_error * std::hypot(camera.image_width, camera.image_height);
  if (defined && rms <= limit) return Status::Ok();
  std::ostringstream msg;
  msg << "the estimate does not explain the junction lines (points " << rms
      << " px RMS from the predicted lines, limit " << limit << " px)";
  return Status::ImplausibleGeometry(msg.str());
}

DepthRecoverer::DepthRecoverer(const RecoverDepthOptions& options,
                               std::unique_ptr<CorridorSolver> solver,
                               std::unique_ptr<DepthRasterizer> rasterizer)
    : options_(options), solver_(std::move(solver)), rasterizer_(std::move(rasterizer)) {}

Status DepthRecoverer::Create(const RecoverDepthOptions& options,
                              std::unique_ptr<DepthRecoverer>* recoverer) {
  std::string why;
  if (!options.Check(&why)) return Status::InvalidArgument(why);
  BuildOpenCvTablesOnce();
  std::unique_ptr<CorridorSolver> solver;
  Status status = CreateSolver(options.solver, options.solver_options, &solver);
  if (!status.ok()) return status;
  std::unique_ptr<DepthRasterizer> rasterizer;
  status = CreateRasterizer(options.rasterizer, options.rasterizer_options, &rasterizer);
  if (!status.ok()) return status;
  recoverer->reset(new DepthRecoverer(options, std::move(solver), std::move(rasterizer)));
  return Status::Ok();
}

Status DepthRecoverer::Recover(const cv::Mat& image, const Camera& camera,
                               RecoverDepthResult* result, const CorridorGeometry* previous,
                               JunctionTrack* track) const {
  const auto start = Clock::now();
  Detect(image, camera, result, track);
  if (result->ReadyToReconstruct()) Reconstruct(camera, result, previous);
  result->times.total = SecondsSince(start);
  return result->status;
}

Status DepthRecoverer::Detect(const cv::Mat& image, const Camera& camera,
                              RecoverDepthResult* result, JunctionTrack* track) const {
  const auto start = Clock::now();
  *result = RecoverDepthResult();
  const auto finish = [&](Status status) {
    result->status = status;
    result->times.perception = SecondsSince(start);
    result->times.total = result->times.perception;
    return status;
  };
  std::string why;
  if (!camera.Check(&why)) return finish(Status::InvalidArgument("camera: " + why));
  cv::Mat bgr;
  Status status = ToBgr(image, camera, &bgr);
  if (!status.ok()) return finish(status);
  result->image = bgr;
  result->camera = camera;
  // In a sequence, the junctions near the previous frame's; they stand for the frame when the
  // track trusts them, else the whole search runs and is checked against them.
  JunctionPair tracked;
  const JunctionPair* previous_junctions =
      track != nullptr && options_.track_junctions ? track->Previous(bgr.size()) : nullptr;
  const bool has_tracked =
      previous_junctions != nullptr && TrackJunctions(bgr, *previous_junctions, options_.perception,
                                                      options_.tracker, &tracked, &why);
  if (has_tracked && track->Trusted(options_.tracker.redetect_interval)) {
    result->junctions = std::move(tracked);
    result->junctions_tracked = true;
    track->Tracked(result->junctions, bgr.size());
    return finish(Status::Ok());
  }
  // When the junction search halves the image and the ceiling/end-wall searches halve it as far or
  // further, one halving of the whole image serves both: the searches' image is halved from it.
  const int junction_scale = WorkingScale(bgr.cols, options_.perception.max_work_width);
  const int search_scale = WorkingScale(bgr.cols, options_.search_max_width);
  if (junction_scale > 1 && search_scale >= junction_scale) {
    const WorkingImage halved = HalveToWidth(bgr, camera, options_.perception.max_work_width);
    status = DetectJunctions(bgr, halved.bgr, options_.perception, &result->junctions);
    result->search = search_scale == junction_scale
                         ? halved
                         : HalveToWidth(halved.bgr, halved.camera, options_.search_max_width);
    result->search.scale = search_scale;
  } else {
    status = DetectJunctions(bgr, options_.perception, &result->junctions);
  }
  if (result->junctions.status.ok() && result->junctions.relaxed_hough) {
    AddFallbackNote("junctions from the second, relaxed Hough look: a faint or broken junction",
                    result);
  }
  if (track != nullptr) {
    track->Searched(result->junctions, bgr.size(),
                    has_tracked && SameJunctions(tracked, result->junctions,
                                                 options_.tracker.agreement_px));
  }
  if (!status.ok()) return finish(status);
  return finish(result->junctions.status);
}

Status DepthRecoverer::Reconstruct(const Camera& camera, RecoverDepthResult* result,
                                   const CorridorGeometry* previous) const {
  const auto start = Clock::now();
  const auto finish = [&](Status status) {
    result->status = status;
    result->times.total = result->times.perception + SecondsSince(start);
    return status;
  };
  auto stage = Clock::now();
  CorridorGeometry geometry;
  Status status;
  if (!result->junctions.status.ok()) {
    // One junction hidden: with a known width (the previous frame's, else the option) the other
    // wall follows; never a made-up second line. Otherwise the detector's reason stands.
    if (!result->junctions.has_single) return finish(result->junctions.status);
    const double width = previous != nullptr ? previous->width : options_.width_prior;
    status = GeometryFromOneJunction(result->junctions, camera, width, previous, &geometry,
                                     &result->fallback);
    if (previous != nullptr && status.ok()) result->fallback += " (previous frame)";
    result->times.solve = SecondsSince(stage);
    if (!status.ok()) {
      return finish(Status(status.code(), result->junctions.status.message() + "; " +
                                              status.message()));
    }
    status = CheckPlausible(geometry, options_);
    if (!status.ok()) return finish(status);
  } else {
    const CorridorObservation observation =
        ObservationFromJunctions(result->junctions, camera, options_.points_per_line);
    status = solver_->Solve(observation, nullptr, &result->solver_summary);
    result->times.solve = SecondsSince(stage);
    if (!status.ok()) {
      if (status.code() == StatusCode::kInvalidArgument) {
        status = Status::NoCorridorFound("junction lines unusable: " + status.message());
      }
      return finish(status);
    }
    geometry = result->solver_summary.estimate;
    geometry.camera_height = camera.mount_height;
    status = CheckPlausible(geometry, options_);
    if (status.ok()) status = CheckLineFit(geometry, observation, camera, options_);
    if (!status.ok()) return finish(status);
  }
  geometry.ceiling_height = options_.ceiling_height;
  stage = Clock::now();
  // The ceiling and end-wall searches share one image at the search resolution.
  const bool search_ceiling =
      options_.ceiling_height <= 0 && options_.estimate_ceiling && !result->image.empty();
  const bool search_end_wall = options_.estimate_end_wall && !result->image.empty();
  WorkingImage search;
  if (search_ceiling || search_end_wall) {
    search = result->search.bgr.empty()
                 ? HalveToWidth(result->image, camera, options_.search_max_width)
                 : result->search;
  }
  // The search image's edges, shared by the frame's searches: when the end-wall search reads the
  // image at its own resolution, it needs all of them, computed once here; otherwise the first
  // ceiling search computes the rows it needs, and the checks' searches reuse them.
  ImageEdges edges;
  if (search_end_wall && WorkingScale(search.bgr.cols, options_.end_wall.max_work_width) == 1) {
    ComputeImageEdges(search.bgr, &edges);
  }
  if (search_ceiling) {
    status = SearchCeiling(search, &edges, &geometry, &result->ceiling);
    if (!status.ok()) return finish(status);
    bool lower_taken = false;
    if (options_.ceiling_checks_baseboards && result->junctions.status.ok()) {
      lower_taken = CheckBaseboards(camera, search, &edges, &geometry, result);
      result->lower_line_taken = lower_taken;
    }
    // A lower line taken has made the two ceiling sides agree: nothing for the inner-line check.
    if (options_.ceiling_checks_inner_lines && result->junctions.status.ok() && !lower_taken) {
      status = MoveInnerWall(search, &edges, previous, &geometry, result);
      if (!status.ok()) return finish(status);
    }
  }
  // The width hold comes after the checks, which may have moved a wall out with this frame's own
  // evidence. A width still much narrower whose two ceiling junctions, each searched alone, agree
  // (within 6%: what the baseboard check needs no check for) is this frame's walls confirmed: the
  // previous frame's wider width was the wrong one, and holding it would carry the mistake on.
  // (Only a width from two junctions: with one, the previous width is already this frame's.)
  const CorridorGeometry* hold_from = result->junctions.status.ok() ? previous : nullptr;
  if (hold_from != nullptr && MuchNarrower(*hold_from, options_.max_width_change, geometry)) {
    const double disagreement =
        search_ceiling ? CeilingDisagreement(result->ceiling, geometry.camera_height) : -1;
    if (!(disagreement >= 0 && disagreement <= std::log(kSidesAgree))) {
      HoldWidth(*hold_from, options_.max_width_change, &geometry, result);
      if (search_ceiling) {  // The ceiling of the held walls.
        status = SearchCeiling(search, &edges, &geometry, &result->ceiling);
        if (!status.ok()) return finish(status);
      }
    }
  }
  if (search_ceiling) {
    HoldCeiling(previous, options_.max_ceiling_disagreement, options_.ceiling.min_support,
                &geometry, result);
    if (hold_from != nullptr) {
      ScaleWallsToCeiling(*hold_from, options_.max_ceiling_change, &geometry, result);
    }
  }
  result->times.ceiling = SecondsSince(stage);
  stage = Clock::now();
  if (search_end_wall) {
    status =
        DetectEndWall(search.bgr, search.camera, geometry, options_.end_wall, &result->end_wall,
                      &edges);
    if (!status.ok()) return finish(status);
    if (result->end_wall.found) geometry.end_distance = result->end_wall.distance;
  }
  result->times.end_wall = SecondsSince(stage);
  result->geometry = geometry;
  // The frame's confidence, from the evidence for this geometry.
  FrameEvidence& evidence = result->evidence;
  const JunctionPair& junctions = result->junctions;
  const JunctionLine* lines[2] = {nullptr, nullptr};
  if (junctions.status.ok()) {
    lines[0] = &junctions.left, lines[1] = &junctions.right;
  } else if (junctions.has_single) {
    lines[junctions.single_is_left ? 0 : 1] = &junctions.single;
  }
  for (int s = 0; s < 2; ++s) {
    if (lines[s] == nullptr) continue;
    evidence.junction[s] = lines[s]->confidence;
    if (!search.bgr.empty()) {
      evidence.crossings[s] = CountVerticalCrossings(search.bgr, search.camera, search.scale,
                                                     geometry, *lines[s],
                                                     options_.vertical_crossings);
    }
  }
  evidence.ceiling_disagreement =
      search_ceiling ? CeilingDisagreement(result->ceiling, geometry.camera_height) : -1;
  evidence.corrected = !junctions.status.ok() || result->width_held || result->walls_scaled ||
                       result->lower_line_taken;
  evidence.moved_side = result->moved_side;
  std::string weakest;
  result->confidence = FrameConfidence(evidence, &weakest);
  if (result->confidence < options_.min_confidence) {
    std::ostringstream msg;
    msg.precision(2);
    msg << std::fixed << "confidence " << result->confidence << " is below "
        << options_.min_confidence << ": " << weakest;
    return finish(Status::LowConfidence(msg.str()));
  }
  result->has_geometry = true;

  stage = Clock::now();
  status = rasterizer_->Render(geometry, camera, &result->depth);
  if (status.ok()) MarkNoEstimateNaN(&result->depth);
  result->times.rasterize = SecondsSince(stage);
  return finish(status);
}

bool DepthRecoverer::CheckBaseboards(const Camera& camera, const WorkingImage& search,
                                     ImageEdges* edges, CorridorGeometry* geometry,
                                     RecoverDepthResult* result) const {
  // Heights that agree within 6% need no check; a lower line must bring them within 8%, and to
  // less than half the disagreement.
  // Without two sides strong enough to compare (as when the upper line has skewed the whole
  // geometry, so that neither ceiling junction is where it is sought), a lower line must find
  // both, each with the ceiling search's own minimum support, agreeing within 3%: two weak
  // searches that agree that closely do not do so by chance.
  const double agree = std::log(kSidesAgree), accept = std::log(1.08),
               weak_accept = std::log(1.03);
  const double before = CeilingDisagreement(result->ceiling, geometry->camera_height);
  if (before >= 0 && before <= agree) return false;
  const bool compared = before >= 0;
  // A lower line must also halve `best` (the disagreement so far); without a comparison it starts
  // at twice weak_accept, so that only the weak_accept bound applies to the first one.
  double best = compared ? before : 2 * weak_accept;
  int best_side = -1;
  CorridorGeometry best_geometry;
  SolverSummary best_summary;
  CeilingEstimate best_ceiling;
  for (int side = 0; side < 2; ++side) {
    const JunctionPair& found = result->junctions;
    if (!(side == 0 ? found.has_left_lower : found.has_right_lower)) continue;
    JunctionPair pair = result->junctions;
    (side == 0 ? pair.left : pair.right) = side == 0 ? pair.left_lower : pair.right_lower;
    const CorridorObservation observation =
        ObservationFromJunctions(pair, camera, options_.points_per_line);
    SolverSummary summary;
    if (!solver_->Solve(observation, nullptr, &summary).ok()) continue;
    CorridorGeometry g = summary.estimate;
    g.camera_height = camera.mount_height;
    if (!CheckPlausible(g, options_).ok() || !CheckLineFit(g, observation, camera, options_).ok()) {
      continue;
    }
    CeilingEstimate ceiling;
    if (!DetectCeiling(search.bgr, search.camera, g, options_.ceiling, &ceiling, edges).ok()) {
      continue;
    }
    const double after =
        compared ? CeilingDisagreement(ceiling, g.camera_height)
                 : CeilingDisagreement(ceiling, g.camera_height, options_.ceiling.min_support);
    if (after < 0 || after > (compared ? accept : weak_accept) || after > 0.5 * best) continue;
    best = after;
    best_side = side;
    best_geometry = g;
    best_summary = summary;
    best_ceiling = ceiling;
  }
  if (best_side < 0) return false;
  JunctionPair& pair = result->junctions;
  if (best_side == 0) {
    pair.left = pair.left_lower;
  } else {
    pair.right = pair.right_lower;
  }
  const Eigen::Vector3d vp = pair.left.line.cross(pair.right.line);
  if (std::abs(vp.z()) > 1e-12) pair.vanishing_point = vp.head<2>() / vp.z();
  result->solver_summary = best_summary;
  result->ceiling = best_ceiling;
  best_geometry.ceiling_height = best_ceiling.height;
  *geometry = best_geometry;
  AddFallbackNote(std::string(best_side == 0 ? "left" : "right") +
                      " junction: the lower of two parallel lines (the upper one a baseboard's "
                      "top or a recess's floor line), with which both ceiling junctions agree",
                  result);
  return true;
}

Status DepthRecoverer::SearchCeiling(const WorkingImage& search, ImageEdges* edges,
                                     CorridorGeometry* geometry, CeilingEstimate* estimate) const {
  const Status status =
      DetectCeiling(search.bgr, search.camera, *geometry, options_.ceiling, estimate, edges);
  if (status.ok()) {
    geometry->ceiling_height = estimate->found ? estimate->height : options_.ceiling_height;
  }
  return status;
}

Status DepthRecoverer::MoveInnerWall(const WorkingImage& search, ImageEdges* edges,
                                     const CorridorGeometry* previous, CorridorGeometry* geometry,
                                     RecoverDepthResult* result) const {
  // Both ceiling junctions found where the walls put them, agreeing: nothing to check. Neither
  // found: no side to trust (the trusted one must be in the ceiling search's range).
  const CeilingEstimate& found = result->ceiling;
  const double disagreement = CeilingDisagreement(found, geometry->camera_height);
  if ((disagreement >= 0 &&
       disagreement <= std::log(1 + MinInnerLineDisagreement(options_.inner_line))) ||
      std::max(found.side_visible_support[0], found.side_visible_support[1]) <
          options_.inner_line.min_support) {
    return Status::Ok();
  }
  CorridorGeometry moved = *geometry;
  const InnerLineCheck check =
      CheckInnerLine(search.bgr, search.camera, options_.ceiling, options_.inner_line, &moved,
                     edges, {result->junctions.has_left_lower, result->junctions.has_right_lower});
  if (!check.moved || !CheckPlausible(moved, options_).ok()) return Status::Ok();
  // In a sequence the previous frame's width must agree better with the moved wall than with the
  // line it replaces (a misjudged side would otherwise carry on through the width hold).
  if (previous != nullptr && previous->width > 0 &&
      std::abs(std::log(moved.width / previous->width)) >=
          std::abs(std::log(geometry->width / previous->width))) {
    return Status::Ok();
  }
  CeilingEstimate ceiling;
  const Status status = SearchCeiling(search, edges, &moved, &ceiling);
  if (!status.ok()) return status;
  result->ceiling = ceiling;
  *geometry = moved;
  result->moved_side = check.side;
  AddFallbackNote(DescribeInnerLineCheck(check), result);
  return Status::Ok();
}

Status RecoverDepth(const cv::Mat& image, const Camera& camera, const RecoverDepthOptions& options,
                    RecoverDepthResult* result) {
  std::unique_ptr<DepthRecoverer> recoverer;
  const Status status = DepthRecoverer::Create(options, &recoverer);
  if (!status.ok()) {
    *result = RecoverDepthResult();
    result->status = status;
    return status;
  }
  return recoverer->Recover(image, camera, result);
}

}  // namespace corridor
