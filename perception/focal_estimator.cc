#include "perception/focal_estimator.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <sstream>
#include <vector>

#include <Eigen/Dense>
#include <opencv2/imgproc.hpp>

#include "corridor_depth/camera.h"
#include "perception/focal_lines.h"

namespace corridor {
namespace {

constexpr int kMinImageSide = 24;  // Smaller images hold no usable lines.

bool Fail(std::string* why, const std::string& message) {
  if (why != nullptr) *why = message;
  return false;
}

// Focal length of a horizontal field of view, as Camera::FromHorizontalFov computes it.
double FocalOfHfov(int width, double hfov_deg) {
  return Camera::FromHorizontalFov(width, 1, hfov_deg * M_PI / 180.0, 0).fx;
}

// Where the vanishing points may be and how lines meet them.
struct FocalSearch {
  Eigen::Vector2d centre;               // Principal point, px.
  double inlier_distance = 1.5;         // px, see FocalEstimatorOptions::inlier_distance_px.
  double robust_scale = 0.3;            // px, see FocalEstimatorOptions::robust_scale_px.
  bool zero_roll = true;                // See FocalEstimatorOptions::assume_zero_roll.
  int pairs = 3000;                     // Line pairs per RANSAC.
  double min_focal = 0, max_focal = 0;  // Plausible focal lengths, px.
};

// How far the line misses the vanishing point vp (homogeneous, any scale, may be at infinity),
// px, signed: the rms distance of its endpoints from the best line through vp, to first order,
// (a x b).vp / (sqrt(2) sqrt(|w a - v|^2 + |w b - v|^2)) with vp = (v, w). For a far vp it is the
// endpoint distance from the line through the midpoint and vp; unlike that, it stays smooth
// when vp lies on or near the segment itself.
double Residual(const ImageLine& s, const Eigen::Vector3d& vp) {
  const Eigen::Vector2d v = vp.head<2>();
  const double w = vp.z();
  const double scale = std::sqrt(2.0 * ((w * s.a.head<2>() - v).squaredNorm() +
                                        (w * s.b.head<2>() - v).squaredNorm()));
  if (!(scale > 0)) return std::numeric_limits<double>::infinity();
  return s.through.dot(vp) / scale;
}

// Calls f(i, j) for every pair i < j of n items, or for `pairs` random pairs when there are more.
template <class F>
void ForPairs(int n, int pairs, std::mt19937* rng, F&& f) {
  if (n < 2) return;
  if (static_cast<long long>(n) * (n - 1) / 2 <= pairs) {
    for (int i = 0; i < n; ++i) {
      for (int j = i + 1; j < n; ++j) f(i, j);
    }
    return;
  }
  std::uniform_int_distribution<int> pick(0, n - 1);
  for (int k = 0; k < pairs; ++k) {
    const int i = pick(*rng), j = pick(*rng);
    if (i != j) f(i, j);
  }
}

// The finite vanishing point within `max_distance` of the centre met by the longest total length
// of lines (RANSAC over line pairs), refined by weighted least squares; its lines in *inliers.
bool FindCorridorVp(const std::vector<ImageLine>& lines, const FocalSearch& search,
                    double max_distance, std::mt19937* rng, Eigen::Vector3d* vp,
                    std::vector<int>* inliers) {
  double best = 0;
  Eigen::Vector3d best_vp = Eigen::Vector3d::Zero();
  ForPairs(static_cast<int>(lines.size()), search.pairs, rng, [&](int i, int j) {
    Eigen::Vector3d v = lines[i].line.cross(lines[j].line);
    if (!(std::abs(v.z()) > 1e-12 * v.norm())) return;
    if ((v.hnormalized() - search.centre).norm() > max_distance) return;
    v.normalize();
    double score = 0;
    for (const ImageLine& l : lines) {
      const double x = Residual(l, v) / search.inlier_distance;  // Tight fits score more.
      if (std::abs(x) < 1) score += l.length * (1 - x * x);
    }
    if (score > best) best = score, best_vp = v;
  });
  if (!(best > 0)) return false;
  Eigen::Vector3d v = best_vp;
  for (int round = 0; round < 3; ++round) {
    inliers->clear();
    Eigen::Matrix2d a = Eigen::Matrix2d::Zero();
    Eigen::Vector2d b = Eigen::Vector2d::Zero();
    const Eigen::Vector2d p = v.hnormalized();
    for (size_t i = 0; i < lines.size(); ++i) {
      if (!(std::abs(Residual(lines[i], v)) < search.inlier_distance)) continue;
      inliers->push_back(static_cast<int>(i));
      // Weighted so that the point-to-line distance reads as an endpoint distance.
      const double d = std::max(1.0, (lines[i].mid.hnormalized() - p).norm());
      const double w = std::pow(0.5 * lines[i].length / d, 2);
      const Eigen::Vector2d n = lines[i].line.head<2>();
      a += w * n * n.transpose();
      b -= w * lines[i].line.z() * n;
    }
    if (inliers->size() < 2 || std::abs(a.determinant()) < 1e-12 * a.squaredNorm()) break;
    const Eigen::Vector2d refined = a.ldlt().solve(b);
    if (!refined.allFinite() || (refined - search.centre).norm() > max_distance) break;
    v = refined.homogeneous().normalized();
  }
  *vp = v;
  return !inliers->empty();
}

// The corridor's frame seen by the camera: P_C = R P_W with R = R_z(roll) R_x(pitch) R_y(yaw)
// (docs/geometry.md, plus a roll), and the focal length that images it.
struct ManhattanFrame {
  double focal = 0;                     // px.
  double pitch = 0, yaw = 0, roll = 0;  // rad.
};

// Columns: the directions of the corridor's axis (family 0), across it (1) and vertical (2).
Eigen::Matrix3d Directions(const ManhattanFrame& f) {
  const Eigen::Matrix3d r = (Eigen::AngleAxisd(f.roll, Eigen::Vector3d::UnitZ()) *
                             Eigen::AngleAxisd(f.pitch, Eigen::Vector3d::UnitX()) *
                             Eigen::AngleAxisd(f.yaw, Eigen::Vector3d::UnitY()))
                                .toRotationMatrix();
  Eigen::Matrix3d d;
  d << r.col(2), r.col(0), r.col(1);
  return d;
}

// Homogeneous (unit norm) vanishing point of the frame's direction k.
Eigen::Vector3d FrameVp(const ManhattanFrame& f, int k, const Eigen::Vector2d& c) {
  const Eigen::Vector3d d = Directions(f).col(k);
  return Eigen::Vector3d(f.focal * d.x() + c.x() * d.z(), f.focal * d.y() + c.y() * d.z(), d.z())
      .normalized();
}

// Unit direction of the homogeneous image point p for focal f.
Eigen::Vector3d Direction(const Eigen::Vector3d& p, double f, const Eigen::Vector2d& c) {
  return Eigen::Vector3d((p.x() - p.z() * c.x()) / f, (p.y() - p.z() * c.y()) / f, p.z())
      .normalized();
}

// The frame whose corridor direction images to v1 and whose across or vertical direction (the
// nearer to d2's) images to v2, for focal f; zero roll when asked.
ManhattanFrame FrameOf(const Eigen::Vector3d& v1, const Eigen::Vector3d& v2, double f,
                       const Eigen::Vector2d& c, bool zero_roll) {
  const Eigen::Vector3d axis = Direction(v1, f, c) * (v1.z() < 0 ? -1.0 : 1.0);
  const Eigen::Vector3d d2 = Direction(v2, f, c);
  Eigen::Vector3d across, vertical;
  if (std::abs(d2.y()) > std::abs(d2.x())) {
    vertical = d2.y() < 0 ? -d2 : d2;
    across = vertical.cross(axis).normalized();
  } else {
    across = d2.x() < 0 ? -d2 : d2;
    across = (across - across.dot(axis) * axis).normalized();
  }
  vertical = axis.cross(across);
  Eigen::Matrix3d r;
  r << across, vertical, axis;
  ManhattanFrame frame;
  frame.focal = f;
  frame.pitch = std::asin(std::clamp(r(2, 1), -1.0, 1.0));
  frame.yaw = std::atan2(-r(2, 0), r(2, 2));
  const Eigen::Matrix3d m = (Eigen::AngleAxisd(frame.pitch, Eigen::Vector3d::UnitX()) *
                             Eigen::AngleAxisd(frame.yaw, Eigen::Vector3d::UnitY()))
                                .toRotationMatrix();
  const Eigen::Matrix3d rz = r * m.transpose();
  frame.roll = zero_roll ? 0.0 : std::atan2(rz(1, 0), rz(0, 0));
  return frame;
}

// RANSAC over pairs of the lines that miss v1: their meeting point v2 gives f^2 =
// -(v1 - c).(v2 - c), hence a frame (FrameOf) and its across and vertical vanishing points;
// scored by the length of the lines that meet one of them, the tighter the better.
bool FindOrthogonalVps(const std::vector<ImageLine>& lines, const std::vector<int>& corridor_lines,
                       const FocalSearch& search, const Eigen::Vector3d& v1, std::mt19937* rng,
                       ManhattanFrame* frame) {
  std::vector<char> on_v1(lines.size(), 0);
  for (int i : corridor_lines) on_v1[i] = 1;
  std::vector<int> rest;
  for (size_t i = 0; i < lines.size(); ++i) {
    if (!on_v1[i]) rest.push_back(static_cast<int>(i));
  }
  const Eigen::Vector2d c = search.centre;
  const Eigen::Vector2d a = v1.hnormalized() - c;
  double best = 0;
  ForPairs(static_cast<int>(rest.size()), search.pairs, rng, [&](int i, int j) {
    Eigen::Vector3d v2 = lines[rest[i]].line.cross(lines[rest[j]].line);
    if (!(v2.norm() > 0)) return;
    v2.normalize();
    if (!(std::abs(v2.z()) > 1e-15)) return;
    const double f2 = -a.dot(v2.head<2>() - v2.z() * c) / v2.z();
    if (!(f2 >= search.min_focal * search.min_focal && f2 <= search.max_focal * search.max_focal)) {
      return;
    }
    const ManhattanFrame candidate = FrameOf(v1, v2, std::sqrt(f2), c, search.zero_roll);
    const Eigen::Vector3d v2_model = FrameVp(candidate, 1, c), v3 = FrameVp(candidate, 2, c);
    double score = 0;
    for (int k : rest) {
      const double r = std::min(std::abs(Residual(lines[k], v2_model)), std::abs(Residual(lines[k], v3)));
      const double x = r / search.inlier_distance;  // Tight fits score more.
      if (x < 1) score += lines[k].length * (1 - x * x);
    }
    if (score > best) best = score, *frame = candidate;
  });
  return best > 0;
}

struct FrameFit {
  int support[3] = {0, 0, 0};  // Lines per direction.
  double rms = 0;              // px.
};

// Each line's direction (-1: none): the vanishing point it meets best, within the distance.
std::vector<int> Assign(const std::vector<ImageLine>& lines, const FocalSearch& search,
                        const ManhattanFrame& frame, FrameFit* fit) {
  const Eigen::Vector3d vps[3] = {FrameVp(frame, 0, search.centre),
                                  FrameVp(frame, 1, search.centre),
                                  FrameVp(frame, 2, search.centre)};
  std::vector<int> family(lines.size(), -1);
  *fit = FrameFit();
  double sum = 0;
  for (size_t i = 0; i < lines.size(); ++i) {
    double best = search.inlier_distance;
    for (int k = 0; k < 3; ++k) {
      const double r = std::abs(Residual(lines[i], vps[k]));
      if (r < best) best = r, family[i] = k;
    }
    if (family[i] >= 0) ++fit->support[family[i]], sum += best * best;
  }
  const int total = fit->support[0] + fit->support[1] + fit->support[2];
  fit->rms = total > 0 ? std::sqrt(sum / total) : 0;
  return family;
}

// The frame moved by x = (log focal change, pitch, yaw, roll changes).
ManhattanFrame Moved(const ManhattanFrame& f, const Eigen::Vector4d& x) {
  ManhattanFrame moved = f;
  moved.focal = f.focal * std::exp(x(0));
  moved.pitch += x(1);
  moved.yaw += x(2);
  moved.roll += x(3);
  return moved;
}

// The assigned lines' residuals, each times its weight.
Eigen::VectorXd Residuals(const std::vector<ImageLine>& lines, const std::vector<int>& family,
                          const std::vector<double>& weight, const ManhattanFrame& frame,
                          const Eigen::Vector2d& c) {
  const Eigen::Vector3d vps[3] = {FrameVp(frame, 0, c), FrameVp(frame, 1, c), FrameVp(frame, 2, c)};
  std::vector<double> r;
  for (size_t i = 0; i < lines.size(); ++i) {
    if (family[i] >= 0) r.push_back(weight[i] * std::clamp(Residual(lines[i], vps[family[i]]), -1e3, 1e3));
  }
  return Eigen::Map<Eigen::VectorXd>(r.data(), static_cast<Eigen::Index>(r.size()));
}

// Levenberg-Marquardt over (focal, rotation) on the residuals of the assigned lines (numeric
// Jacobian: four parameters), alternated with the assignment and with Cauchy weights
// (iteratively reweighted least squares): a few lines are biased (two edges merged, the edges of
// a thin bar that the blur pushes apart) and the rest are accurate to a tenth of a pixel.
void RefineFrame(const std::vector<ImageLine>& lines, const FocalSearch& search, int min_corridor,
                 int min_other, ManhattanFrame* frame, FrameFit* fit) {
  for (int round = 0; round < 5; ++round) {
    std::vector<int> family = Assign(lines, search, *frame, fit);
    std::vector<double> weight(lines.size(), 0.0);
    for (size_t i = 0; i < lines.size(); ++i) {
      int& k = family[i];
      if (k >= 0 && fit->support[k] < (k == 0 ? min_corridor : min_other)) k = -1;
      if (k < 0) continue;
      const double r = Residual(lines[i], FrameVp(*frame, k, search.centre)) / search.robust_scale;
      weight[i] = 1 / std::sqrt(1 + r * r);
    }
    Eigen::VectorXd r = Residuals(lines, family, weight, *frame, search.centre);
    double cost = r.squaredNorm(), lambda = 1e-3;
    const int n = search.zero_roll ? 3 : 4;  // Parameters: log focal, pitch, yaw (, roll).
    for (int iteration = 0; iteration < 50 && r.size() >= n; ++iteration) {
      Eigen::MatrixXd jacobian(r.size(), n);
      for (int p = 0; p < n; ++p) {
        Eigen::Vector4d h = Eigen::Vector4d::Zero();
        h(p) = 1e-6;
        jacobian.col(p) = (Residuals(lines, family, weight, Moved(*frame, h), search.centre) -
                           Residuals(lines, family, weight, Moved(*frame, -h), search.centre)) /
                          2e-6;
      }
      const Eigen::MatrixXd normal = jacobian.transpose() * jacobian;
      const Eigen::VectorXd gradient = jacobian.transpose() * r;
      bool improved = false;
      while (lambda < 1e8 && !improved) {
        Eigen::MatrixXd damped = normal;
        damped.diagonal() *= 1 + lambda;
        Eigen::Vector4d step = Eigen::Vector4d::Zero();
        step.head(n) = -damped.ldlt().solve(gradient);
        const ManhattanFrame next = Moved(*frame, step);
        const Eigen::VectorXd next_r = Residuals(lines, family, weight, next, search.centre);
        if (step.allFinite() && next_r.squaredNorm() < cost) {
          improved = true;
          *frame = next;
          r = next_r;
          const double previous = cost;
          cost = r.squaredNorm();
          lambda = std::max(1e-9, lambda / 10);
          if (previous - cost < 1e-12 * previous || step.norm() < 1e-12) iteration = 50;
        } else {
          lambda *= 10;
        }
      }
      if (!improved) break;
    }
  }
  Assign(lines, search, *frame, fit);
}

std::string Fallback(const std::string& reason, int width, double hfov_deg, FocalEstimate* e) {
  std::ostringstream how;
  how << reason << ": fell back to --hfov=" << hfov_deg;
  e->focal_px = FocalOfHfov(width, hfov_deg);
  e->from_vanishing_points = false;
  return how.str();
}

}  // namespace

bool FocalEstimatorOptions::Check(std::string* why) const {
  const auto positive = [](double x) { return std::isfinite(x) && x > 0; };
  const auto non_negative = [](double x) { return std::isfinite(x) && x >= 0; };
  if (!non_negative(blur_sigma)) return Fail(why, "blur_sigma must be finite and >= 0");
  if (!(canny_low_ratio > 0 && canny_low_ratio <= 1)) return Fail(why, "canny_low_ratio must be in (0, 1]");
  if (!(canny_auto_percentile > 0 && canny_auto_percentile < 100)) {
    return Fail(why, "canny_auto_percentile must be in (0, 100)");
  }
  if (!non_negative(canny_auto_min)) return Fail(why, "canny_auto_min must be finite and >= 0");
  if (hough_threshold < 1) return Fail(why, "hough_threshold must be >= 1");
  if (!(hough_min_length_fraction > 0 && hough_min_length_fraction < 1)) {
    return Fail(why, "hough_min_length_fraction must be in (0, 1)");
  }
  if (!non_negative(hough_max_gap)) return Fail(why, "hough_max_gap must be finite and >= 0");
  if (!(merge_angle_deg > 0 && merge_angle_deg < 45)) return Fail(why, "merge_angle_deg must be in (0, 45)");
  if (!positive(merge_distance_px)) return Fail(why, "merge_distance_px must be finite and > 0");
  if (!(min_line_length_fraction >= 0 && min_line_length_fraction < 1)) {
    return Fail(why, "min_line_length_fraction must be in [0, 1)");
  }
  if (!non_negative(refit_distance_px)) return Fail(why, "refit_distance_px must be finite and >= 0");
  if (!positive(inlier_distance_px)) return Fail(why, "inlier_distance_px must be finite and > 0");
  if (!positive(robust_scale_px)) return Fail(why, "robust_scale_px must be finite and > 0");
  if (ransac_pairs < 1) return Fail(why, "ransac_pairs must be >= 1");
  if (!positive(max_corridor_vp_distance)) return Fail(why, "max_corridor_vp_distance must be finite and > 0");
  if (min_corridor_support < 2) return Fail(why, "min_corridor_support must be >= 2");
  if (min_second_support < 2) return Fail(why, "min_second_support must be >= 2");
  if (!(min_hfov_deg > 0 && min_hfov_deg < max_hfov_deg && max_hfov_deg < 180)) {
    return Fail(why, "need 0 < min_hfov_deg < max_hfov_deg < 180");
  }
  if (!positive(max_second_vp_distance)) return Fail(why, "max_second_vp_distance must be finite and > 0");
  return true;
}

Status EstimateFocal(const cv::Mat& bgr_image, const FocalEstimatorOptions& options,
                     double fallback_hfov_deg, FocalEstimate* estimate) {
  if (estimate == nullptr) return Status::InvalidArgument("EstimateFocal: estimate is null");
  *estimate = FocalEstimate();
  std::string why;
  if (!options.Check(&why)) return Status::InvalidArgument("focal estimator options: " + why);
  if (!(std::isfinite(fallback_hfov_deg) && fallback_hfov_deg > 0 && fallback_hfov_deg < 180)) {
    std::ostringstream msg;
    msg << "fallback horizontal field of view " << fallback_hfov_deg
        << " deg must be finite and in (0, 180)";
    return Status::InvalidArgument(msg.str());
  }
  if (bgr_image.empty()) return Status::InvalidArgument("image is empty");
  if (bgr_image.depth() != CV_8U) return Status::InvalidArgument("image must be 8-bit");
  if (bgr_image.cols < kMinImageSide || bgr_image.rows < kMinImageSide) {
    std::ostringstream msg;
    msg << "image " << bgr_image.cols << "x" << bgr_image.rows << " is smaller than "
        << kMinImageSide << "x" << kMinImageSide;
    return Status::InvalidArgument(msg.str());
  }
  cv::Mat color;
  if (bgr_image.channels() == 1) {
    cv::cvtColor(bgr_image, color, cv::COLOR_GRAY2BGR);
  } else if (bgr_image.channels() == 4) {
    cv::cvtColor(bgr_image, color, cv::COLOR_BGRA2BGR);
  } else if (bgr_image.channels() == 3) {
    color = bgr_image;
  } else {
    return Status::InvalidArgument("image must have 1, 3 or 4 channels");
  }

  const int width = color.cols;
  const Eigen::Vector2d centre(0.5 * (color.cols - 1), 0.5 * (color.rows - 1));
  const double diagonal = std::hypot(color.cols, color.rows);
  FocalSearch search;
  search.centre = centre;
  search.inlier_distance = options.inlier_distance_px;
  search.robust_scale = options.robust_scale_px;
  search.zero_roll = options.assume_zero_roll;
  search.pairs = options.ransac_pairs;
  search.min_focal = FocalOfHfov(width, options.max_hfov_deg);
  search.max_focal = FocalOfHfov(width, options.min_hfov_deg);
  std::mt19937 rng(options.seed);

  const std::vector<ImageLine> lines = FindFocalLines(color, options);
  std::vector<int> corridor_lines;
  Eigen::Vector3d v1;
  if (!FindCorridorVp(lines, search, options.max_corridor_vp_distance * diagonal, &rng, &v1,
                      &corridor_lines) ||
      static_cast<int>(corridor_lines.size()) < options.min_corridor_support) {
    estimate->how = Fallback("no vanishing point found", width, fallback_hfov_deg, estimate);
    return Status::Ok();
  }
  estimate->corridor_vp = v1.hnormalized();
  estimate->corridor_support = static_cast<int>(corridor_lines.size());

  ManhattanFrame frame;
  if (!FindOrthogonalVps(lines, corridor_lines, search, v1, &rng, &frame)) {
    estimate->how = Fallback("only one vanishing point found (the corridor's)", width,
                             fallback_hfov_deg, estimate);
    return Status::Ok();
  }
  FrameFit fit;
  RefineFrame(lines, search, options.min_corridor_support, options.min_second_support, &frame,
              &fit);
  estimate->corridor_vp = FrameVp(frame, 0, centre).hnormalized();
  estimate->corridor_support = fit.support[0];
  estimate->rms_px = fit.rms;
  // The orthogonal vanishing point nearest the centre fixes f best: f^2 = -(v1 - c).(v2 - c).
  int second = 0;
  double nearest = std::numeric_limits<double>::infinity();
  for (int k = 1; k <= 2; ++k) {
    const Eigen::Vector3d d = Directions(frame).col(k);
    const double distance = d.head<2>().norm() / std::max(1e-300, std::abs(d.z()));  // In focal lengths.
    if (fit.support[k] >= options.min_second_support && distance < nearest) {
      nearest = distance;
      second = k;
    }
  }
  if (second == 0) {
    estimate->how = Fallback("only one vanishing point found (the corridor's)", width,
                             fallback_hfov_deg, estimate);
    return Status::Ok();
  }
  const Eigen::Vector3d d2 = Directions(frame).col(second);
  estimate->second_support = fit.support[second];
  estimate->third_support = fit.support[3 - second];
  estimate->second_family = second == 1 ? "across" : "vertical";
  if (std::abs(d2.z()) > 1e-12) estimate->second_vp = FrameVp(frame, second, centre).hnormalized();
  if (nearest > options.max_second_vp_distance) {
    std::ostringstream reason;
    reason << "the " << estimate->second_family << " vanishing point is " << nearest
           << " focal lengths from the centre (ill-conditioned, limit "
           << options.max_second_vp_distance << ")";
    estimate->how = Fallback(reason.str(), width, fallback_hfov_deg, estimate);
    return Status::Ok();
  }
  if (!(frame.focal >= search.min_focal && frame.focal <= search.max_focal)) {
    std::ostringstream reason;
    reason << "the vanishing points give f = " << frame.focal << " px, outside hfov "
           << options.min_hfov_deg << "-" << options.max_hfov_deg << " deg";
    estimate->how = Fallback(reason.str(), width, fallback_hfov_deg, estimate);
    return Status::Ok();
  }
  estimate->focal_px = frame.focal;
  estimate->from_vanishing_points = true;
  std::ostringstream how;
  how << "vanishing points (corridor + " << estimate->second_family;
  if (estimate->third_support >= options.min_second_support) {
    how << " + " << (estimate->second_family == "across" ? "vertical" : "across");
  }
  how << ")";
  estimate->how = how.str();
  return Status::Ok();
}

}  // namespace corridor
