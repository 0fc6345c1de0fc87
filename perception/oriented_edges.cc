#include "perception/oriented_edges.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "kernels/binomial_blur.h"
#include "kernels/canny_edges.h"
#include "kernels/color_gradient.h"
#include "kernels/edge_scan.h"

namespace corridor {
namespace {

// Rows of edges computed beyond the band, for the blur and Canny's gradients and hysteresis.
constexpr int kBandMargin = 8;
// Rows a cache of edges reaches below the band that filled it, in hundredths of the image's
// height: a later search of the frame, with the walls moved, reaches a little farther down.
constexpr int kCacheSlackPercent = 4;

// out(r, u) = the OR of bits over the 3x3 pixels around (r, u) inside the image: the OR of three
// neighbours along each row, then of three such rows.
void OrNeighbourhoods(const cv::Mat& bits, cv::Mat* out) {
  const int rows = bits.rows, cols = bits.cols;
  std::vector<uchar> along((rows + 2) * static_cast<size_t>(cols), 0);  // A zero row each end.
  for (int r = 0; r < rows; ++r) {
    const uchar* b = bits.ptr<uchar>(r);
    uchar* h = along.data() + (r + 1) * static_cast<size_t>(cols);
    h[0] = static_cast<uchar>(b[0] | (cols > 1 ? b[1] : 0));
    for (int u = 1; u + 1 < cols; ++u) h[u] = static_cast<uchar>(b[u - 1] | b[u] | b[u + 1]);
    if (cols > 1) h[cols - 1] = static_cast<uchar>(b[cols - 2] | b[cols - 1]);
  }
  for (int r = 0; r < rows; ++r) {
    const uchar* above = along.data() + r * static_cast<size_t>(cols);
    const uchar* centre = above + cols;
    const uchar* below = centre + cols;
    uchar* o = out->ptr<uchar>(r);
    for (int u = 0; u < cols; ++u) o[u] = static_cast<uchar>(above[u] | centre[u] | below[u]);
  }
}

}  // namespace

int OrientationBin(int gx, int gy) {
  // Turned into [0, 180] degrees: an edge and its reverse are the same edge (gy = 0 with gx < 0
  // stays at 180 degrees, the last bin, as atan2 puts it). In double: no integer overflow.
  const double flip = gy < 0 ? -1.0 : 1.0;
  const double x = flip * gx, y = flip * gy, ax = std::abs(x);
  // The bin edges' tangents: tan(22.5 deg) = sqrt(2) - 1, tan(67.5 deg) = sqrt(2) + 1; at 45 and
  // 135 degrees the comparison is exact (integers in double). Both halves are counted and one
  // selected, without branches (edge orientations do not follow a pattern a branch predictor
  // could learn): right of vertical, the edges y crosses; left of it, 7 less those y exceeds.
  constexpr double kTan22 = 0.41421356237309504880, kTan67 = 2.41421356237309504880;
  const int right = (y >= kTan22 * ax) + (y >= ax) + (y >= kTan67 * ax);
  const int left = 7 - (y > kTan22 * ax) - (y > ax) - (y > kTan67 * ax);
  const int vertical = y == 0 ? 0 : 4;
  return x > 0 ? right : (x < 0 ? left : vertical);
}

bool ColorCannyEdges(const cv::Mat& bgr, int from, int to, cv::Mat* dx, cv::Mat* dy,
                     cv::Mat* edges) {
  cv::Mat smooth;
  if (!BinomialBlur(bgr, from, to, 5, &smooth).ok()) return false;
  ColorGradient(smooth, dx, dy, nullptr);
  return CannyFromGradients(*dx, *dy, 20, 60, true, edges).ok();
}

bool ImageEdges::Covers(const cv::Mat& image, int bottom) const {
  if (edges.empty() || image_rows != image.rows || edges.cols != image.cols ||
      dx.size() != edges.size() || dy.size() != edges.size()) {
    return false;
  }
  return edges.rows == image.rows || bottom + kBandMargin <= edges.rows;
}

namespace {

// The image's rows [0, to) into *out; false (and *out empty) as ColorCannyEdges.
bool EdgesFromTop(const cv::Mat& bgr, int to, ImageEdges* out) {
  *out = ImageEdges();
  if (bgr.empty() || !ColorCannyEdges(bgr, 0, to, &out->dx, &out->dy, &out->edges)) {
    *out = ImageEdges();
    return false;
  }
  out->image_rows = bgr.rows;
  return true;
}

}  // namespace

bool ComputeImageEdges(const cv::Mat& bgr, ImageEdges* out) {
  return EdgesFromTop(bgr, bgr.rows, out);
}

OrientedEdges ComputeOrientedEdges(const cv::Mat& bgr, int top, int bottom, ImageEdges* cache) {
  OrientedEdges out;
  top = std::clamp(top, 0, bgr.rows);
  bottom = std::clamp(bottom, top, bgr.rows);
  out.top = top;
  if (bottom <= top) return out;
  int from = 0;
  cv::Mat dx, dy, edges;
  if (cache != nullptr) {
    if (!cache->Covers(bgr, bottom)) {
      const int slack = kCacheSlackPercent * bgr.rows / 100;
      if (!EdgesFromTop(bgr, std::min(bgr.rows, bottom + kBandMargin + slack), cache)) {
        return out;  // Not 8-bit: no edges.
      }
    }
    dx = cache->dx;
    dy = cache->dy;
    edges = cache->edges;
  } else {
    from = std::max(0, top - kBandMargin);
    const int to = std::min(bgr.rows, bottom + kBandMargin);
    if (!ColorCannyEdges(bgr, from, to, &dx, &dy, &edges)) return out;  // Not 8-bit: no edges.
  }
  const cv::Rect band(0, top - from, bgr.cols, bottom - top);
  out.edges = edges(band).clone();
  // Each edge pixel's orientation bit, OR-ed over its 3x3 neighbourhood.
  cv::Mat bits = cv::Mat::zeros(band.size(), CV_8U);
  ForEachEdgePixel(out.edges, [&](int u, int r) {
    const int row = r + band.y;
    bits.at<uchar>(r, u) =
        static_cast<uchar>(1u << OrientationBin(dx.at<short>(row, u), dy.at<short>(row, u)));
  });
  out.near.create(band.size(), CV_8U);
  OrNeighbourhoods(bits, &out.near);
  return out;
}

LineHits OrientedLineHits(const cv::Point* line, int samples, const OrientedEdges& edges) {
  LineHits out;
  const int rows = edges.near.rows;
  const auto inside = [&](const cv::Point& p) {
    return p.x >= 0 && p.x < edges.near.cols && p.y >= edges.top && p.y < edges.top + rows;
  };
  int first = -1, last = -1, visible = 0;
  for (int i = 0; i < samples; ++i) {
    if (!inside(line[i])) continue;
    if (first < 0) first = i;
    last = i;
    ++visible;
  }
  out.visible = visible;
  if (visible < 8) return out;
  // The line's normal, from its two visible ends (straight up to the lens distortion).
  const cv::Point d = line[last] - line[first];
  const int bin = OrientationBin(-d.y, d.x);
  uchar mask = 0;
  for (int k = -1; k <= 1; ++k) {
    mask |= static_cast<uchar>(1u << ((bin + k + kOrientationBins) % kOrientationBins));
  }
  int hits = 0;
  for (int i = first; i <= last; ++i) {
    if (!inside(line[i])) continue;
    hits += (edges.near.ptr<uchar>(line[i].y - edges.top)[line[i].x] & mask) != 0;
  }
  out.hits = hits;
  return out;
}

double LineHits::Fraction(int at_least) const {
  if (visible < 8) return 0.0;
  return static_cast<double>(hits) / std::max(visible, at_least);
}

}  // namespace corridor
