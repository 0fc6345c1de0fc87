#include "perception/vertical_crossings.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/corridor_frame.h"
#include "perception/oriented_edges.h"

namespace corridor {
namespace {

// One examined point of the junction: its pixel, the image direction of "up" on the wall there,
// and the length in pixels of the band above it.
struct BandPoint {
  Eigen::Vector2d pixel;
  Eigen::Vector2d up;
  double length = 0;
};

// Is there an edge running along `up` within 1 px of (x, y) (edges.near's bits)?
bool VerticalEdgeAt(const OrientedEdges& edges, int expected_bin, double x, double y) {
  const int u = static_cast<int>(std::lround(x)), v = static_cast<int>(std::lround(y)) - edges.top;
  if (u < 0 || v < 0 || u >= edges.near.cols || v >= edges.near.rows) return false;
  const int bits = edges.near.at<uchar>(v, u);
  const int before = (expected_bin + kOrientationBins - 1) % kOrientationBins;
  const int after = (expected_bin + 1) % kOrientationBins;
  return (bits & ((1 << expected_bin) | (1 << before) | (1 << after))) != 0;
}

// The band from the point along `direction` (from 2 px on, its length): the fraction of it on
// vertical edges, and its mean contrast across `up` (the largest gradient across it within 1 px).
struct Run {
  double fraction = 0;
  double contrast = 0;
};
Run BandRun(const OrientedEdges& edges, const ImageEdges& gradient, int bin, const BandPoint& p,
            const Eigen::Vector2d& direction) {
  const Eigen::Vector2d across(-p.up.y(), p.up.x());
  int on = 0, n = 0;
  double contrast = 0;
  for (double k = 2; k <= p.length; k += 1, ++n) {
    const Eigen::Vector2d q = p.pixel + k * direction;
    on += VerticalEdgeAt(edges, bin, q.x(), q.y());
    double best = 0;
    for (int d = -1; d <= 1; ++d) {
      const int u = static_cast<int>(std::lround(q.x() + d * across.x()));
      const int v = static_cast<int>(std::lround(q.y() + d * across.y()));
      if (u < 0 || v < 0 || u >= gradient.dx.cols || v >= gradient.dx.rows) continue;
      const double g = std::abs(gradient.dx.at<short>(v, u) * across.x() +
                                gradient.dy.at<short>(v, u) * across.y());
      best = std::max(best, g);
    }
    contrast += best;
  }
  Run run;
  if (n > 0) run.fraction = static_cast<double>(on) / n, run.contrast = contrast / n;
  return run;
}

}  // namespace

bool VerticalCrossingOptions::Check(std::string* why) const {
  if (!(band_height > 0 && band_height < 3)) {
    *why = "band_height must be in (0, 3) m";
  } else if (!(min_band_px >= 3)) {
    *why = "min_band_px must be at least 3";
  } else if (!(min_run > 0 && min_run <= 1)) {
    *why = "min_run must be in (0, 1]";
  } else if (!(min_contrast_ratio >= 0 && min_contrast_ratio <= 10)) {
    *why = "min_contrast_ratio must be in [0, 10]";
  } else if (step_px < 1) {
    *why = "step_px must be at least 1";
  } else {
    return true;
  }
  return false;
}

VerticalCrossings CountVerticalCrossings(const cv::Mat& bgr, const Camera& camera, int scale,
                                         const CorridorGeometry& g, int side,
                                         const JunctionLine& line,
                                         const VerticalCrossingOptions& options,
                                         ImageEdges* cache) {
  VerticalCrossings out;
  if (bgr.empty() || scale < 1 || !(g.camera_height > 0)) return out;
  const CorridorRotation<double> r(g.pitch, g.yaw);
  const Vec3<double> n = r.FloorNormal();  // Down, in the camera frame.
  const Eigen::Vector2d a = line.near_end / scale, b = line.far_end / scale;
  const double span = (b - a).norm();
  if (!(span >= 2)) return out;
  // The junction's points, each with the direction of "up" on the wall and the band's length: the
  // floor point seen at the pixel, and the point band_height above it, projected.
  std::vector<BandPoint> points;
  int top = bgr.rows, bottom = 0;
  for (double t = 0; t <= span; t += options.step_px) {
    const Eigen::Vector2d pixel = a + (b - a) * (t / span);
    const Vec3<double> ray = RayOfRawPixel(camera, pixel.x(), pixel.y());
    const double along = n.x * ray.x + n.y * ray.y + n.z * ray.z;
    if (!(along > 1e-6)) continue;  // The ray does not meet the floor.
    const double depth = g.camera_height / along;
    const Eigen::Vector3d floor_point(depth * ray.x, depth * ray.y, depth * ray.z);
    const Eigen::Vector3d above = floor_point - options.band_height * Eigen::Vector3d(n.x, n.y, n.z);
    if (!(above.z() > 0.05)) continue;
    Eigen::Vector2d up_pixel = camera.Project(above);
    if (camera.HasDistortion()) up_pixel = camera.Distort(up_pixel);
    const Eigen::Vector2d up = up_pixel - pixel;
    BandPoint p{pixel, up.normalized(), up.norm()};
    if (!(p.length >= options.min_band_px) || !p.up.allFinite()) continue;
    points.push_back(p);
    const double y_above = pixel.y() - p.length - 2, y_below = pixel.y() + p.length + 2;
    top = std::min(top, static_cast<int>(std::floor(std::min(y_above, y_below))));
    bottom = std::max(bottom, static_cast<int>(std::ceil(std::max(y_above, y_below))) + 1);
  }
  (void)side;
  if (points.empty()) return out;
  // Through a cache of the image's edges from the top down, whose gradients give the contrast.
  ImageEdges local;
  ImageEdges* gradient = cache != nullptr ? cache : &local;
  const OrientedEdges edges =
      ComputeOrientedEdges(bgr, std::max(0, top), std::min(bgr.rows, bottom), gradient);
  if (edges.near.empty()) return out;
  // Runs of consecutive points whose band above is on a vertical edge: one edge reaching down to
  // the junction; it crosses when, somewhere along the run, the band below is on one too, of
  // nearly the same contrast (a glossy floor's reflection of it is fainter).
  bool in_run = false, run_crosses = false;
  const auto end_run = [&] {
    if (in_run) {
      ++out.reaching;
      out.crossing += run_crosses;
    }
    in_run = run_crosses = false;
  };
  for (const BandPoint& p : points) {
    ++out.samples;
    // An edge along `up` has its gradient across it: the bin of the normal to `up`.
    const int bin = OrientationBin(static_cast<int>(std::lround(-1000 * p.up.y())),
                                   static_cast<int>(std::lround(1000 * p.up.x())));
    const Run above = BandRun(edges, *gradient, bin, p, p.up);
    if (above.fraction < options.min_run) {
      end_run();
      continue;
    }
    in_run = true;
    const Run below = BandRun(edges, *gradient, bin, p, -p.up);
    run_crosses = run_crosses || (below.fraction >= options.min_run &&
                                  below.contrast >= options.min_contrast_ratio * above.contrast);
  }
  end_run();
  return out;
}

}  // namespace corridor
