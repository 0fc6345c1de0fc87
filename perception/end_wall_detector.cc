#include "perception/end_wall_detector.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "corridor_depth/corridor_frame.h"
#include "kernels/max_filter.h"
#include "perception/appearance.h"
#include "perception/corridor_projection.h"
#include "perception/oriented_edges.h"
#include "perception/working_image.h"

namespace corridor {
namespace {

// Rows of edges computed beyond those a look-up reads: Canny's hysteresis there sees nearly what
// it sees over the whole image.
constexpr int kEdgeMargin = 8;

// Projects corridor-frame points to raw pixels and looks them up in the edges of the working
// image: the whole image's (UseEdges), or only those of the rows looked at (FromRow, then
// NeedRowsFrom, in place of the whole image's: floor lines lie below the horizon, and the rows
// above it are computed only when a candidate's corners are looked at).
class EdgeProbe {
 public:
  EdgeProbe(const cv::Mat& bgr, const Camera& camera, const CorridorGeometry& g, int reach)
      : bgr_(bgr),
        camera_(camera),
        distorted_(camera.HasDistortion()),
        r_(g.pitch, g.yaw),
        reach_(reach) {}

  // The whole image's edges, computed elsewhere.
  void UseEdges(const cv::Mat& edges) {
    edges_ = edges;
    first_row_ = valid_row_ = 0;
    thread_local cv::Mat thread_near;  // The thread's (one probe at a time), kept frame to frame.
    MaxFilterSquare(edges_, reach_, &thread_near);
    near_ = thread_near;
  }

  // The edges of the rows from `first` down (the whole image's when first <= 0); false (none)
  // for an image that is not 8-bit.
  bool FromRow(int first) {
    first = std::clamp(first, 0, bgr_.rows);
    const int from = std::max(0, first - reach_ - kEdgeMargin);
    cv::Mat dx, dy;
    if (!ColorCannyEdges(bgr_, from, bgr_.rows, &dx, &dy, &edges_)) return false;
    first_row_ = from;
    valid_row_ = from == 0 ? 0 : first;
    MaxFilterSquare(edges_, reach_, &near_);
    return true;
  }

  // Makes the rows from `first` down readable: the rows above those it has are computed (with
  // margins both ways) and joined to them where both sides are a margin away from their ends.
  void NeedRowsFrom(int first) const {
    first = std::max(0, first);
    if (first >= valid_row_) return;
    const int from = std::max(0, first - reach_ - kEdgeMargin);
    // The rows had are used from here down.
    const int seam = std::min(bgr_.rows, first_row_ + kEdgeMargin);
    cv::Mat dx, dy, above;
    ColorCannyEdges(bgr_, from, std::min(bgr_.rows, seam + kEdgeMargin), &dx, &dy, &above);
    cv::Mat edges(bgr_.rows - from, bgr_.cols, CV_8U);
    above.rowRange(0, seam - from).copyTo(edges.rowRange(0, seam - from));
    edges_.rowRange(seam - first_row_, edges_.rows).copyTo(edges.rowRange(seam - from, edges.rows));
    // The dilation changes only down to `reach` below the seam; below, it is the one had.
    const int redone = std::min(edges.rows, seam - from + 2 * reach_ + 1);
    cv::Mat near_above, near(edges.size(), CV_8U);
    MaxFilterSquare(edges.rowRange(0, redone), reach_, &near_above);
    const int kept_from = std::min(edges.rows, seam - from + reach_);
    near_above.rowRange(0, kept_from).copyTo(near.rowRange(0, kept_from));
    near_.rowRange(kept_from + from - first_row_, near_.rows)
        .copyTo(near.rowRange(kept_from, near.rows));
    edges_ = edges;
    near_ = near;
    first_row_ = from;
    valid_row_ = from == 0 ? 0 : first;
  }

  // Raw pixel of (x, y, z), or false when behind the camera or within `reach` of the border.
  bool Project(double x, double y, double z, cv::Point* pixel) const {
    return ProjectCorridorPoint(camera_, distorted_, r_, x, y, z, reach_, pixel);
  }

  // The row of (x, y, z) in the image, rounded down, for an undistorted camera in front of it;
  // 0 otherwise (every row).
  int RowAtMost(double x, double y, double z) const {
    const Vec3<double> c = r_.ToCamera({x, y, z});
    if (distorted_ || c.z < 0.05) return 0;
    const double v = camera_.fy * c.y / c.z + camera_.cy;
    return v > 0 && v < bgr_.rows ? static_cast<int>(std::floor(v)) - 1 : (v > 0 ? bgr_.rows : 0);
  }

  // The horizon's row, rounded down, for an undistorted camera: every floor point lies below it
  // (the camera has no roll in the corridor frame). 0 otherwise.
  int HorizonRow() const {
    const Vec3<double> n = r_.FloorNormal();  // (0, cos pitch, sin pitch) in the camera.
    if (distorted_ || !(n.y > 0)) return 0;
    return std::max(0, static_cast<int>(std::floor(camera_.cy - camera_.fy * n.z / n.y)) - 1);
  }

  // An edge pixel within `reach` px of p (in each direction): one look-up in the dilated map.
  bool NearEdge(const cv::Point& p) const {
    if (p.y < valid_row_) NeedRowsFrom(p.y - 2 * kEdgeMargin);
    return near_.at<uchar>(p.y - first_row_, p.x) != 0;
  }

  // An edge at pixel (u, v).
  bool EdgeAt(int v, int u) const {
    if (v < valid_row_) NeedRowsFrom(v - 2 * kEdgeMargin);
    return edges_.at<uchar>(v - first_row_, u) != 0;
  }

  // Fraction of the visible samples of the segment a-b (corridor frame) near an edge; -1 when
  // fewer than `min_visible` samples are visible. Samples within `keep_away` px of `away` are
  // not counted (they would see the edge at `away` itself). *span gets the visible extent, px.
  double Support(const Vec3<double>& a, const Vec3<double>& b, int samples, int min_visible,
                 double* span = nullptr, const cv::Point* away = nullptr,
                 double keep_away = 0) const {
    int visible = 0, hits = 0;
    cv::Point first, last;
    for (int i = 0; i < samples; ++i) {
      const double t = (i + 0.5) / samples;
      cv::Point p;
      if (!Project(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), a.z + t * (b.z - a.z), &p)) {
        continue;
      }
      if (away != nullptr && std::hypot(p.x - away->x, p.y - away->y) < keep_away) continue;
      if (visible++ == 0) first = p;
      last = p;
      hits += NearEdge(p);
    }
    if (span != nullptr) *span = visible > 1 ? std::hypot(last.x - first.x, last.y - first.y) : 0;
    return visible >= min_visible ? static_cast<double>(hits) / visible : -1.0;
  }

  const CorridorRotation<double>& rotation() const { return r_; }

 private:
  const cv::Mat& bgr_;
  mutable cv::Mat edges_;      // CV_8U, 255 = edge: image rows [first_row_, rows).
  mutable cv::Mat near_;       // edges_ dilated by `reach`.
  mutable int first_row_ = 0;  // Image row of edges_'s first.
  mutable int valid_row_ = 0;  // Look-ups from this image row down need no rows more.
  const Camera& camera_;
  bool distorted_;  // camera_.HasDistortion().
  CorridorRotation<double> r_;
  int reach_;  // px.
};

// How well an end wall at distance D explains the edges.
struct Candidate {
  double distance = 0;
  double support = -1;  // The floor/end-wall line's second-best third.
  double beyond = 0;    // The cleaner junction just beyond D (0 when too short to see).
  double before = 0;    // Strongest junction just before D.
  double corner = 0;    // Strongest vertical wall/end-wall corner.
  double span = 0;      // Visible length of the floor/end-wall line, px.
};

Candidate Score(const EdgeProbe& probe, const CorridorGeometry& g, double d,
                const EndWallDetectorOptions& o) {
  Candidate c;
  c.distance = d;
  const double h = g.camera_height, xl = -g.LeftDistance(), xr = g.RightDistance();
  const int third = std::max(6, o.samples / 3);
  double thirds[3], total_span = 0;
  for (int k = 0; k < 3; ++k) {
    const double x0 = xl + (xr - xl) * (0.05 + 0.3 * k), x1 = x0 + 0.3 * (xr - xl);
    double span = 0;
    thirds[k] = probe.Support({x0, h, d}, {x1, h, d}, third, third / 2, &span);
    if (thirds[k] < 0) return c;  // A third of the line is out of the image.
    total_span += span;
  }
  // Two thirds must follow edges: an object may stand in front of the rest.
  std::sort(thirds, thirds + 3);
  c.support = thirds[1];
  c.span = total_span;
  if (c.support < o.min_support) return c;  // Rejected anyway: skip the rest.
  // The corners' lower part, up to 1.8 m (or the ceiling): doors and the ceiling estimate's error
  // do not reach there.
  const double top = h - (g.HasCeiling() ? std::min(g.ceiling_height, 1.8) : 1.8);
  double beyond = 2;  // The cleaner side's fraction; 2 = neither side measurable.
  // The corners' rows, above the horizon, are computed now if they have not been.
  probe.NeedRowsFrom(std::min({probe.RowAtMost(xl, top, d), probe.RowAtMost(xl, h - 0.1, d),
                               probe.RowAtMost(xr, top, d), probe.RowAtMost(xr, h - 0.1, d)}));
  for (double x : {xl, xr}) {
    cv::Point corner;
    if (!probe.Project(x, h, d, &corner)) continue;
    // Beyond the wall the junction is hidden: few edges there, counted away from the corner (near
    // the vanishing point its samples crowd onto the corner's own edges).
    const double b = probe.Support({x, h, d * 1.05}, {x, h, std::min(d * 2.0, d + 10.0)},
                                   o.samples / 2, 6, nullptr, &corner, 2.0 * o.reach_px + 1);
    const double a = probe.Support({x, h, std::max(d / 1.8, d - 8.0)}, {x, h, d / 1.05},
                                   o.samples / 2, 6);
    const double v = probe.Support({x, h - 0.1, d}, {x, top, d}, o.samples / 2, 6);
    if (b >= 0) beyond = std::min(beyond, b);
    c.before = std::max(c.before, a);
    c.corner = std::max(c.corner, v);
  }
  // One clean side is enough (clutter may stand at the other end); too short to see: unknown.
  c.beyond = beyond > 1 ? 0.0 : beyond;
  return c;
}

// Per-channel median of 8-bit BGR pixels, in 8-bit Lab.
cv::Vec3f MedianLab(const std::vector<cv::Vec3b>& bgr) {
  cv::Mat lab;
  cv::cvtColor(cv::Mat(bgr).reshape(3, 1), lab, cv::COLOR_BGR2Lab);
  cv::Vec3f median;
  for (int k = 0; k < 3; ++k) {
    std::vector<uchar> channel;
    for (int i = 0; i < lab.cols; ++i) channel.push_back(lab.at<cv::Vec3b>(0, i)[k]);
    std::nth_element(channel.begin(), channel.begin() + channel.size() / 2, channel.end());
    median[k] = channel[channel.size() / 2];
  }
  return median;
}

// How different the end wall just above the floor/end-wall line (10-30 cm up) looks from the
// floor just before it: a grout line or a sill has floor on both sides. -1 when unseen.
double AppearanceContrast(const cv::Mat& bgr, const EdgeProbe& probe, const CorridorGeometry& g,
                          double d, int samples) {
  const double h = g.camera_height, xl = -g.LeftDistance(), xr = g.RightDistance();
  std::vector<cv::Vec3b> wall, floor;
  for (int i = 0; i < samples; ++i) {
    const double x = xl + (xr - xl) * (0.2 + 0.6 * (i + 0.5) / samples);
    for (double up : {0.1, 0.2, 0.3}) {
      cv::Point p;
      if (probe.Project(x, h - up, d, &p)) wall.push_back(bgr.at<cv::Vec3b>(p));
    }
    for (double before : {0.9, 0.93, 0.96}) {
      cv::Point p;
      if (probe.Project(x, h, d * before, &p)) floor.push_back(bgr.at<cv::Vec3b>(p));
    }
  }
  if (wall.size() < 6 || floor.size() < 6) return -1;
  return LabDistance(MedianLab(wall), MedianLab(floor));
}

}  // namespace

bool EndWallDetectorOptions::Check(std::string* why) const {
  std::string reason;
  if (!(near_distance > 0 && far_distance > near_distance) || (candidates != 0 && candidates < 10) ||
      samples < 18) {
    reason =
        "end wall search needs 0 < near_distance < far_distance, 0 (automatic) or >= 10 "
        "candidates and >= 18 samples";
  } else if (!(min_support > 0 && min_support <= 1) || !(max_beyond >= 0 && max_beyond < 1) ||
             !(min_before >= 0 && min_before <= 1) || !(min_corner >= 0 && min_corner <= 1) ||
             !(min_contrast >= 0)) {
    reason =
        "end wall: min_support in (0, 1], max_beyond in [0, 1), min_before and min_corner "
        "in [0, 1], min_contrast >= 0";
  } else if (!(min_span >= 0 && min_span < 1) || reach_px < 1 || reach_px > 5 ||
             max_work_width < 64) {
    reason = "end wall: min_span must be in [0, 1), reach_px in [1, 5], max_work_width >= 64";
  }
  if (reason.empty()) return true;
  if (why != nullptr) *why = reason;
  return false;
}

Status DetectEndWall(const cv::Mat& full_bgr, const Camera& full_camera, const CorridorGeometry& g,
                     const EndWallDetectorOptions& o, EndWallEstimate* estimate,
                     const ImageEdges* shared) {
  *estimate = EndWallEstimate();
  std::string why;
  if (!o.Check(&why)) return Status::InvalidArgument("end wall detector: " + why);
  if (full_bgr.empty() || full_bgr.cols != full_camera.image_width ||
      full_bgr.rows != full_camera.image_height) {
    return Status::InvalidArgument("end wall detector: image does not match the camera");
  }
  // Large images are searched at half resolution (or less), with the camera scaled to match; the
  // first halving reuses the blurred rows that came with the shared edges of this image.
  const bool has_blurred = shared != nullptr && shared->image_rows == full_bgr.rows &&
                           shared->smooth.cols == full_bgr.cols;
  // In the thread's buffer, whose halving keeps its memory from call to call (the image itself,
  // when not halved, is not the buffer's to hold).
  thread_local WorkingImage thread_work;
  WorkingImage& work = thread_work;
  HalveToWidth(full_bgr, full_camera, o.max_work_width, has_blurred ? &shared->smooth : nullptr,
               &work);
  if (work.scale == 1) work.bgr.release();
  const cv::Mat& bgr = work.scale == 1 ? full_bgr : work.bgr;
  const Camera& camera = work.camera;
  // Edges of the colour gradient: a dark baseboard on a dark floor has no grey edge. Shared ones
  // are the whole image's; computed here, those of the rows below the horizon first (where every
  // floor point lies), those above only as far up as a candidate's corners reach.
  EdgeProbe probe(bgr, camera, g, o.reach_px);
  if (work.scale == 1 && shared != nullptr && shared->Fits(bgr)) {
    probe.UseEdges(shared->edges);
  } else if (!probe.FromRow(probe.HorizonRow())) {
    estimate->reason = "the image is not 8-bit: no edges to search";
    return Status::Ok();
  }

  // Near the vanishing point everything converges (grout, lights, doors): too few pixels to tell.
  const double min_span_px = std::max(24.0, o.min_span * camera.image_width);
  Candidate best;
  double best_score = -1;
  // Candidates uniform in 1/D, as many as keep the floor/end-wall line within reach_px of the
  // image's line between two of them (its row moves by about f h d(1/D)).
  const int candidates =
      o.candidates > 0
          ? o.candidates
          : std::max(20, static_cast<int>(std::ceil(camera.fy * g.camera_height *
                                                    (1.0 / o.near_distance - 1.0 / o.far_distance) /
                                                    o.reach_px)));
  for (int i = 0; i < candidates; ++i) {
    const double inv = 1.0 / o.near_distance +
                       (1.0 / o.far_distance - 1.0 / o.near_distance) * i / (candidates - 1.0);
    const Candidate c = Score(probe, g, 1.0 / inv, o);
    if (c.support < o.min_support || c.beyond > o.max_beyond || c.before < o.min_before ||
        c.corner < o.min_corner || c.span < min_span_px) {
      continue;
    }
    if (o.min_contrast > 0 && bgr.type() == CV_8UC3) {
      const double contrast = AppearanceContrast(bgr, probe, g, c.distance, o.samples / 2);
      if (contrast >= 0 && contrast < o.min_contrast) continue;
    }
    const double score = c.support + c.corner - c.beyond;
    if (score > best_score) {
      best_score = score;
      best = c;
    }
  }
  if (best_score < 0) {
    estimate->reason = "no line across the corridor where both junctions end";
    return Status::Ok();
  }
  estimate->support = best.support;
  estimate->beyond = best.beyond;
  estimate->corner = best.corner;
  estimate->before = best.before;
  // Refine: every edge pixel within reach + 1 rows of the chosen line gives D from its ray and
  // the floor.
  const CorridorRotation<double>& r = probe.rotation();
  const Vec3<double> n = r.FloorNormal(), axis = r.Axis();
  const double h = g.camera_height, xl = -g.LeftDistance(), xr = g.RightDistance();
  thread_local std::vector<double> thread_distances;  // Keeps its memory from call to call.
  std::vector<double>& distances = thread_distances;
  distances.clear();
  for (int i = 0; i < o.samples; ++i) {
    const double x = xl + (xr - xl) * (0.05 + 0.9 * (i + 0.5) / o.samples);
    cv::Point p;
    if (!probe.Project(x, h, best.distance, &p)) continue;
    for (int dv = -o.reach_px - 1; dv <= o.reach_px + 1; ++dv) {
      const int v = p.y + dv;
      if (v < 0 || v >= bgr.rows || !probe.EdgeAt(v, p.x)) continue;
      const Vec3<double> ray = RayOfRawPixel(camera, p.x, v);
      const double nr = Dot(n, ray);
      if (nr <= 1e-9) continue;
      distances.push_back(h / nr * Dot(axis, ray));  // Z_W of the ray's floor point.
    }
  }
  if (distances.size() < 5) {
    estimate->reason = "too few edge pixels on the floor/end-wall junction";
    return Status::Ok();
  }
  std::nth_element(distances.begin(), distances.begin() + distances.size() / 2, distances.end());
  estimate->distance = distances[distances.size() / 2];
  estimate->points = static_cast<int>(distances.size());
  estimate->found = estimate->distance > 0;
  if (!estimate->found) estimate->reason = "the end wall estimate lies behind the camera";
  return Status::Ok();
}

}  // namespace corridor
