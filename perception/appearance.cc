#include "perception/appearance.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace corridor {
namespace {

float Median(std::vector<float>* values) {
  if (values->empty()) return 0.0f;
  auto mid = values->begin() + values->size() / 2;
  std::nth_element(values->begin(), mid, values->end());
  return *mid;
}

}  // namespace

float LabDistance(const cv::Vec3f& a, const cv::Vec3f& b) {
  const cv::Vec3f d = a - b;
  // 8-bit L is scaled by 255/100, hence 0.25 * (100/255)^2 for a quarter weight on lightness.
  return std::sqrt(0.0385f * d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
}

FloorAppearance SampleFloor(const cv::Mat& lab, int roi_top) {
  const int rows = lab.rows, cols = lab.cols;
  const int image_rows = rows + roi_top;
  const int v0 = std::clamp(static_cast<int>(0.88 * image_rows) - roi_top, 0, rows - 1);
  const int u0 = static_cast<int>(0.35 * cols);
  const int u1 = std::max(u0 + 1, static_cast<int>(0.65 * cols));
  std::vector<float> channel[3];
  std::vector<cv::Vec3f> pixels;
  for (int v = v0; v < rows; v += 2) {
    for (int u = u0; u < u1; u += 2) {
      const cv::Vec3f p = lab.at<cv::Vec3b>(v, u);
      pixels.push_back(p);
      for (int c = 0; c < 3; ++c) channel[c].push_back(p[c]);
    }
  }
  FloorAppearance floor;
  for (int c = 0; c < 3; ++c) floor.lab[c] = Median(&channel[c]);
  std::vector<float> distances;
  for (const auto& p : pixels) distances.push_back(LabDistance(p, floor.lab));
  floor.spread = std::max(1.0f, Median(&distances));
  return floor;
}

double BoundaryScore(const cv::Mat& lab, const FloorAppearance& floor, const MergedLine& line,
                     int roi_top) {
  const Eigen::Vector2d normal = line.line.head<2>();  // Points down (toward the floor).
  const int samples = 24;
  const double offset = 4.0;  // Strip distance from the line, px.
  // Floor-likeness of each strip, per sample, so that a few samples on grout, a box or a door
  // do not decide: the junction has floor just below and something else above. (A baseboard top
  // has baseboard below; a grout line or a reflection has floor on both sides.)
  const double sigma = std::max(6.0, 3.0 * floor.spread);
  const auto likeness = [&](const cv::Vec3f& c) {
    const double d = LabDistance(c, floor.lab);
    return std::exp(-d * d / (2 * sigma * sigma));
  };
  double sum = 0;
  int count = 0;
  for (int i = 0; i < samples; ++i) {
    const Eigen::Vector2d p = line.start + (line.end - line.start) * ((i + 0.5) / samples);
    const Eigen::Vector2d pa = p - offset * normal, pb = p + offset * normal;
    const int ua = cvRound(pa.x()), va = cvRound(pa.y()), ub = cvRound(pb.x()), vb = cvRound(pb.y());
    if (ua < 1 || ub < 1 || ua >= lab.cols - 1 || ub >= lab.cols - 1 || va < roi_top + 1 ||
        vb >= roi_top + lab.rows - 1 || va >= roi_top + lab.rows - 1) {
      continue;
    }
    // 3x3 means on each side.
    cv::Vec3f ca(0, 0, 0), cb(0, 0, 0);
    for (int dv = -1; dv <= 1; ++dv) {
      for (int du = -1; du <= 1; ++du) {
        ca += cv::Vec3f(lab.at<cv::Vec3b>(va - roi_top + dv, ua + du));
        cb += cv::Vec3f(lab.at<cv::Vec3b>(vb - roi_top + dv, ub + du));
      }
    }
    sum += likeness(cb / 9.0f) * (1.0 - likeness(ca / 9.0f));
    ++count;
  }
  return count > 0 ? sum / count : 0.0;
}

}  // namespace corridor
