#include "perception/appearance.h"

#include <algorithm>
#include <initializer_list>
#include <array>
#include <cmath>
#include <vector>

#include <Eigen/Geometry>
#include <opencv2/imgproc.hpp>

namespace corridor {
namespace {

float Median(std::vector<float>* values) {
  if (values->empty()) return 0.0f;
  auto mid = values->begin() + values->size() / 2;
  std::nth_element(values->begin(), mid, values->end());
  return *mid;
}

// The element Median would return (index n / 2 of the sorted values) of n byte values, from
// their counts; 0 when there are none.
float MiddleByte(const std::array<int, 256>& counts, size_t n) {
  if (n == 0) return 0.0f;
  size_t seen = 0;
  for (int value = 0; value < 256; ++value) {
    seen += static_cast<size_t>(counts[value]);
    if (seen > n / 2) return static_cast<float>(value);
  }
  return 255.0f;
}

// The mean colour of the 3x3 pixels around image point p (full-image coordinates; `bgr` holds
// the rows from roi_top). False when they are not all inside.
bool Mean3x3(const cv::Mat& bgr, const Eigen::Vector2d& p, int roi_top, int spacing,
             cv::Vec3b* mean) {
  const int u = cvRound(p.x()), v = cvRound(p.y()) - roi_top;
  if (u < spacing || v < spacing || u >= bgr.cols - spacing || v >= bgr.rows - spacing) {
    return false;
  }
  cv::Vec3i sum(0, 0, 0);
  for (int dv = -spacing; dv <= spacing; dv += spacing) {
    for (int du = -spacing; du <= spacing; du += spacing) {
      sum += cv::Vec3i(bgr.at<cv::Vec3b>(v + dv, u + du));
    }
  }
  *mean = cv::Vec3b(static_cast<uchar>(sum[0] / 9), static_cast<uchar>(sum[1] / 9),
                    static_cast<uchar>(sum[2] / 9));
  return true;
}

// The pixels of `bgr` in 8-bit Lab, into `lab` (its memory kept from call to call).
void BgrToLabInto(const std::vector<cv::Vec3b>& bgr, std::vector<cv::Vec3b>* lab) {
  lab->resize(bgr.size());
  if (bgr.empty()) return;
  // One row of pixels, converted in place of the whole image's conversion.
  const cv::Mat in(1, static_cast<int>(bgr.size()), CV_8UC3, const_cast<cv::Vec3b*>(bgr.data()));
  cv::Mat out(1, static_cast<int>(lab->size()), CV_8UC3, lab->data());
  cv::cvtColor(in, out, cv::COLOR_BGR2Lab);
  CV_Assert(out.data == reinterpret_cast<uchar*>(lab->data()));
}

// The median Lab colour of 8-bit BGR pixels and their median distance to it (at least 1).
FloorAppearance AppearanceOf(const std::vector<cv::Vec3b>& patch) {
  // Each channel's median (the middle element, as Median takes it) from a count of its 256
  // values instead of a partial sort.
  std::array<std::array<int, 256>, 3> counts{};
  // The thread's buffers, kept from frame to frame.
  thread_local std::vector<cv::Vec3b> lab;
  thread_local std::vector<float> distances;
  BgrToLabInto(patch, &lab);
  for (const cv::Vec3b& pixel : lab) {
    for (int c = 0; c < 3; ++c) ++counts[c][pixel[c]];
  }
  FloorAppearance floor;
  for (int c = 0; c < 3; ++c) floor.lab[c] = MiddleByte(counts[c], lab.size());
  distances.clear();
  for (const cv::Vec3b& pixel : lab) distances.push_back(LabDistance(cv::Vec3f(pixel), floor.lab));
  floor.spread = std::max(1.0f, Median(&distances));
  return floor;
}

// Floor-likeness of a mean Lab colour: a Gaussian of its distance to the floor's colour, as wide
// as the floor's own texture allows.
double Likeness(const cv::Vec3f& lab, const FloorAppearance& floor) {
  const double sigma = std::max(6.0, 3.0 * floor.spread);
  const double d = LabDistance(lab, floor.lab);
  return std::exp(-d * d / (2 * sigma * sigma));
}

// The 3x3 patches (pixels `scale` apart, 9 per usable sample) centred `offset` times `scale` px
// from 24 points along `line`: below it for offset > 0, above for offset < 0; into `patches`.
void StripPatches(const cv::Mat& bgr, const MergedLine& line, int roi_top, int scale,
                  double offset, std::vector<cv::Vec3b>* patches) {
  const Eigen::Vector2d normal = line.line.head<2>();  // Points down (toward the floor).
  const int samples = 24;
  const int spacing = std::max(1, scale);
  patches->clear();
  for (int i = 0; i < samples; ++i) {
    const Eigen::Vector2d p = line.start + (line.end - line.start) * ((i + 0.5) / samples);
    const Eigen::Vector2d q = p + offset * spacing * normal;
    const int u = cvRound(q.x()), v = cvRound(q.y()) - roi_top;
    if (u < spacing || v < spacing || u >= bgr.cols - spacing || v >= bgr.rows - spacing) continue;
    for (int dv = -spacing; dv <= spacing; dv += spacing) {
      for (int du = -spacing; du <= spacing; du += spacing) {
        patches->push_back(bgr.at<cv::Vec3b>(v + dv, u + du));
      }
    }
  }
}

}  // namespace

float LabDistance(const cv::Vec3f& a, const cv::Vec3f& b) {
  const cv::Vec3f d = a - b;
  // 8-bit L is scaled by 255/100, hence 0.25 * (100/255)^2 for a quarter weight on lightness.
  return std::sqrt(0.0385f * d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
}

std::vector<cv::Vec3b> BgrToLab(const std::vector<cv::Vec3b>& bgr) {
  std::vector<cv::Vec3b> lab;
  BgrToLabInto(bgr, &lab);
  return lab;
}

FloorAppearance SampleFloor(const cv::Mat& bgr, int roi_top, int step) {
  step = std::max(1, step);
  const int rows = bgr.rows, cols = bgr.cols;
  const int image_rows = rows + roi_top;
  const int v0 = std::clamp(static_cast<int>(0.88 * image_rows) - roi_top, 0, rows - 1);
  const int u0 = static_cast<int>(0.35 * cols);
  const int u1 = std::max(u0 + 1, static_cast<int>(0.65 * cols));
  thread_local std::vector<cv::Vec3b> patch;
  patch.clear();
  for (int v = v0; v < rows; v += step) {
    for (int u = u0; u < u1; u += step) patch.push_back(bgr.at<cv::Vec3b>(v, u));
  }
  return AppearanceOf(patch);
}

FloorAppearance SampleBelowLine(const cv::Mat& bgr, const MergedLine& line, int roi_top,
                                int scale) {
  thread_local std::vector<cv::Vec3b> strip;
  StripPatches(bgr, line, roi_top, scale, 4.0, &strip);
  return AppearanceOf(strip);
}

double BoundaryScore(const cv::Mat& bgr, const FloorAppearance& floor, const MergedLine& line,
                     int roi_top, int scale) {
  const Eigen::Vector2d normal = line.line.head<2>();  // Points down (toward the floor).
  const int samples = 24;
  const int spacing = std::max(1, scale);  // Patch pixel spacing, px.
  const double offset = 4.0 * spacing;     // Strip distance from the line, px.
  // The 3x3 patches on each side of every usable sample: 9 above, then 9 below.
  thread_local std::vector<cv::Vec3b> patches, lab;
  patches.clear();
  for (int i = 0; i < samples; ++i) {
    const Eigen::Vector2d p = line.start + (line.end - line.start) * ((i + 0.5) / samples);
    const Eigen::Vector2d pa = p - offset * normal, pb = p + offset * normal;
    const int ua = cvRound(pa.x()), va = cvRound(pa.y()), ub = cvRound(pb.x()), vb = cvRound(pb.y());
    if (ua < spacing || ub < spacing || ua >= bgr.cols - spacing || ub >= bgr.cols - spacing ||
        va < roi_top + spacing || vb >= roi_top + bgr.rows - spacing ||
        va >= roi_top + bgr.rows - spacing) {
      continue;
    }
    for (const cv::Point centre : {cv::Point(ua, va - roi_top), cv::Point(ub, vb - roi_top)}) {
      for (int dv = -spacing; dv <= spacing; dv += spacing) {
        for (int du = -spacing; du <= spacing; du += spacing) {
          patches.push_back(bgr.at<cv::Vec3b>(centre.y + dv, centre.x + du));
        }
      }
    }
  }
  BgrToLabInto(patches, &lab);
  // Floor-likeness of each strip, per sample, so that a few samples on grout, a box or a door
  // do not decide: the junction has floor just below and something else above. (A baseboard top
  // has baseboard below; a grout line or a reflection has floor on both sides.)
  double sum = 0;
  const int count = static_cast<int>(lab.size() / 18);
  for (int s = 0; s < count; ++s) {
    // 3x3 means on each side.
    cv::Vec3f ca(0, 0, 0), cb(0, 0, 0);
    for (int k = 0; k < 9; ++k) {
      ca += cv::Vec3f(lab[18 * s + k]);
      cb += cv::Vec3f(lab[18 * s + 9 + k]);
    }
    sum += Likeness(cb / 9.0f, floor) * (1.0 - Likeness(ca / 9.0f, floor));
  }
  return count > 0 ? sum / count : 0.0;
}

double FloorLikenessBelow(const cv::Mat& bgr, const FloorAppearance& floor,
                          const std::vector<Eigen::Vector2d>& points, const Eigen::Vector2d& normal,
                          int roi_top, int scale) {
  const int spacing = std::max(1, scale);
  thread_local std::vector<cv::Vec3b> patches, lab;
  patches.clear();
  for (const Eigen::Vector2d& p : points) {
    const Eigen::Vector2d q = p + 4.0 * spacing * normal;
    const int u = cvRound(q.x()), v = cvRound(q.y()) - roi_top;
    if (u < spacing || v < spacing || u >= bgr.cols - spacing || v >= bgr.rows - spacing) continue;
    for (int dv = -spacing; dv <= spacing; dv += spacing) {
      for (int du = -spacing; du <= spacing; du += spacing) {
        patches.push_back(bgr.at<cv::Vec3b>(v + dv, u + du));
      }
    }
  }
  BgrToLabInto(patches, &lab);
  const size_t count = lab.size() / 9;
  if (count == 0) return -1;
  double sum = 0;
  for (size_t s = 0; s < count; ++s) {
    cv::Vec3f mean(0, 0, 0);
    for (size_t k = 0; k < 9; ++k) mean += cv::Vec3f(lab[9 * s + k]);
    sum += Likeness(mean / 9.0f, floor);
  }
  return sum / static_cast<double>(count);
}

double FloorLikenessAbove(const cv::Mat& bgr, const FloorAppearance& floor,
                          const MergedLine& line, int roi_top, int scale) {
  thread_local std::vector<cv::Vec3b> strip, lab;
  StripPatches(bgr, line, roi_top, scale, -4.0, &strip);
  BgrToLabInto(strip, &lab);
  const size_t count = lab.size() / 9;
  double sum = 0;
  for (size_t s = 0; s < count; ++s) {
    cv::Vec3f mean(0, 0, 0);
    for (size_t k = 0; k < 9; ++k) mean += cv::Vec3f(lab[9 * s + k]);
    sum += Likeness(mean / 9.0f, floor);
  }
  return count > 0 ? sum / static_cast<double>(count) : 0.0;
}

namespace {

// The colours across the band between `upper` and `lower` (BandContrast's lines) at 24 samples
// along their common extent where the band is at least 4 `scale` px tall: per usable sample, the
// 3x3 means `fractions` of the band's height above `lower` (at most 7), then the floor 3 `scale`
// px below it, appended to *colours. False when the lines have no common extent.
bool BandColours(const cv::Mat& bgr, const MergedLine& upper, const MergedLine& lower, int roi_top,
                 int scale, std::initializer_list<double> fractions,
                 std::vector<cv::Vec3b>* colours) {
  const int spacing = std::max(1, scale);  // Patch pixel spacing, px.
  const double u0 = std::max(upper.start.x(), lower.start.x());
  const double u1 = std::min(upper.end.x(), lower.end.x());
  if (u1 <= u0 || std::abs(lower.line.y()) < 1e-6) return false;
  const Eigen::Vector2d down = lower.line.head<2>();  // Unit normal toward the floor.
  const int samples = 24;
  cv::Vec3b c[8];
  const size_t n = std::min<size_t>(fractions.size(), 7);
  for (int i = 0; i < samples; ++i) {
    const double u = u0 + (u1 - u0) * (i + 0.5) / samples;
    // The lower line's point at column u (b > 0: the line is not vertical).
    const Eigen::Vector2d p(u, -(lower.line.x() * u + lower.line.z()) / lower.line.y());
    const double gap = upper.line.dot(p.homogeneous());  // > 0: p lies below `upper`.
    if (gap < 4.0 * spacing) continue;
    size_t m = 0;
    for (const double f : fractions) {
      if (m == n || !Mean3x3(bgr, p - f * gap * down, roi_top, spacing, &c[m])) break;
      ++m;
    }
    if (m < n || !Mean3x3(bgr, p + 3.0 * spacing * down, roi_top, spacing, &c[n])) continue;
    colours->insert(colours->end(), c, c + n + 1);
  }
  return true;
}

}  // namespace

double BandContrast(const cv::Mat& bgr, const FloorAppearance& floor, const MergedLine& upper,
                    const MergedLine& lower, int roi_top, int scale) {
  // Per usable sample: the band's middle, then the floor below (the thread's buffers).
  thread_local std::vector<cv::Vec3b> pairs, lab;
  thread_local std::vector<float> distances;
  pairs.clear();
  if (!BandColours(bgr, upper, lower, roi_top, scale, {0.5}, &pairs)) return -1.0;
  if (pairs.size() < 12) return -1.0;
  BgrToLabInto(pairs, &lab);
  distances.clear();
  for (size_t k = 0; k + 1 < lab.size(); k += 2) {
    distances.push_back(LabDistance(cv::Vec3f(lab[k]), cv::Vec3f(lab[k + 1])));
  }
  return Median(&distances) / floor.spread;
}

double BandFade(const cv::Mat& bgr, const MergedLine& upper, const MergedLine& lower, int roi_top,
                int scale) {
  // Per usable sample: three quarters up, a quarter up, the middle, the floor below.
  thread_local std::vector<cv::Vec3b> quads, lab;
  thread_local std::vector<float> ratios;
  quads.clear();
  if (!BandColours(bgr, upper, lower, roi_top, scale, {0.75, 0.25, 0.5}, &quads)) return -1.0;
  if (quads.size() < 24) return -1.0;
  BgrToLabInto(quads, &lab);
  ratios.clear();
  for (size_t k = 0; k + 3 < lab.size(); k += 4) {
    const float across = LabDistance(cv::Vec3f(lab[k + 2]), cv::Vec3f(lab[k + 3]));
    ratios.push_back(LabDistance(cv::Vec3f(lab[k]), cv::Vec3f(lab[k + 1])) /
                     std::max(across, 1.0f));
  }
  return Median(&ratios);
}

}  // namespace corridor
