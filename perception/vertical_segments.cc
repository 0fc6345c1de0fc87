#include "perception/vertical_segments.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "kernels/channel_plane.h"
#include "kernels/edge_scan.h"
#include "kernels/sobel_row.h"

namespace corridor {
namespace {

// A chain of peaks, one per scanned row, with the sums of a least-squares fit x = a + b y.
struct Chain {
  double n = 0, sy = 0, sx = 0, syy = 0, sxy = 0, sxx = 0;
  int first_row = 0, last_row = 0;
  double last_x = 0;
  int sign = 0;

  void Add(double x, int y) {
    n += 1, sy += y, sx += x, syy += double(y) * y, sxy += x * y, sxx += x * x;
    last_row = y;
    last_x = x;
  }
};

struct Peak {
  double x;
  int sign;
};

}  // namespace

bool VerticalSegmentOptions::Check(std::string* why) const {
  std::string reason;
  if (row_step < 1 || row_step > 8) {
    reason = "vertical segments: row_step must be in [1, 8]";
  } else if (!(min_gradient > 0) || !(min_length_px > row_step) || !(max_rms_px > 0)) {
    reason = "vertical segments: min_gradient and max_rms_px must be > 0, min_length_px > row_step";
  } else if (!(max_tilt_deg > 0 && max_tilt_deg < 45)) {
    reason = "vertical segments: max_tilt_deg must be in (0, 45)";
  }
  if (why != nullptr) *why = reason;
  return reason.empty();
}

std::vector<cv::Vec4d> FindVerticalSegments(const cv::Mat& grey,
                                            const VerticalSegmentOptions& options,
                                            const std::vector<cv::Vec2i>& skip) {
  std::vector<cv::Vec4d> out;
  FindVerticalSegments(grey, options, skip, &out);
  return out;
}

void FindVerticalSegments(const cv::Mat& grey, const VerticalSegmentOptions& options,
                          const std::vector<cv::Vec2i>& skip, std::vector<cv::Vec4d>* segments) {
  std::vector<cv::Vec4d>& out = *segments;
  out.clear();
  if (grey.empty() || grey.depth() != CV_8U || grey.rows < 3 || grey.cols < 3) return;
  // One channel: the image's own, or a colour image's green (index 1 of BGR): door frames and
  // corners are edges in every channel, and green is the one a colour camera samples best. It is
  // taken out as a plane of its own, so that the rows' loops below read contiguous bytes and the
  // compiler vectorises them.
  thread_local cv::Mat green;  // The thread's buffer: a stream of frames of one size allocates
                               // nothing here.
  const cv::Mat* plane = &grey;
  if (grey.channels() > 1) {
    if (grey.channels() > 4) return;
    ChannelPlane(grey, 1, &green);
    plane = &green;
  }
  thread_local std::vector<short> row;
  thread_local std::vector<uchar> strong;
  row.assign(grey.cols, 0);
  strong.assign(grey.cols, 0);
  const double max_slope = std::tan(options.max_tilt_deg * M_PI / 180.0);
  // A chain continues to a peak at most this far from its last one, per scanned row (a gap of
  // one scanned row allowed).
  const double reach = options.row_step * max_slope + 0.75;

  thread_local std::vector<Chain> chains;
  thread_local std::vector<int> open, next_open;  // Chains that may still continue, by last_x.
  thread_local std::vector<Peak> peaks;
  thread_local std::vector<char> taken;
  chains.clear();
  open.clear();
  const auto close = [&](const Chain& c) {
    if (c.last_row - c.first_row < options.min_length_px) return;
    const double det = c.n * c.syy - c.sy * c.sy;
    if (!(det > 0)) return;
    const double b = (c.n * c.sxy - c.sy * c.sx) / det;
    const double a = (c.sx - b * c.sy) / c.n;
    if (std::abs(b) > max_slope) return;
    // Residual sum of squares of the least-squares line: sxx - a sx - b sxy.
    const double rss = std::max(0.0, c.sxx - a * c.sx - b * c.sxy);
    if (rss > options.max_rms_px * options.max_rms_px * c.n) return;
    out.emplace_back(a + b * c.first_row, c.first_row, a + b * c.last_row, c.last_row);
  };

  const int threshold = static_cast<int>(std::ceil(options.min_gradient));
  const int cols = grey.cols;
  for (int y = 1; y < grey.rows - 1; y += options.row_step) {
    // The columns scanned: [1, cols - 1) less the row's skipped span.
    int span_begin = cols - 1, span_end = cols - 1;
    if (static_cast<int>(skip.size()) == grey.rows && skip[y][1] > skip[y][0]) {
      span_begin = std::max(1, skip[y][0]);
      span_end = std::min(cols - 1, skip[y][1]);
    }
    // The 3x3 Sobel x on the scanned columns (and one more each side, for the peak test), and
    // where it is strong enough for a peak.
    const uchar* up = plane->ptr<uchar>(y - 1);
    const uchar* mid = plane->ptr<uchar>(y);
    const uchar* down = plane->ptr<uchar>(y + 1);
    short* g = row.data();
    uchar* s = strong.data();
    const auto sobel = [&](int begin, int end) {
      SobelXRow(up, mid, down, std::max(1, begin), std::min(cols - 1, end), threshold, g, s);
    };
    sobel(1, span_begin + 1);
    sobel(span_end - 1, cols - 1);
    peaks.clear();
    const auto peak = [&](int x) {
      const int m = std::abs(g[x]);
      const int l = std::abs(g[x - 1]), r = std::abs(g[x + 1]);
      if (m < l || m <= r) return;
      const double curvature = l - 2.0 * m + r;
      const double offset = curvature < 0 ? 0.5 * (l - r) / curvature : 0.0;
      peaks.push_back({x + offset, g[x] > 0 ? 1 : -1});
    };
    const int first_end = std::min(span_begin, cols - 1);
    ForEachNonZeroByte(s, 1, first_end, peak);
    if (first_end < cols - 1) ForEachNonZeroByte(s, std::max(span_end, first_end), cols - 1, peak);
    // Each peak continues the nearest open chain of its sign within reach; each chain takes one.
    taken.assign(open.size(), 0);
    next_open.clear();
    size_t lo = 0;
    for (const Peak& p : peaks) {
      while (lo < open.size() && chains[open[lo]].last_x < p.x - reach) ++lo;
      int best = -1;
      double best_d = reach;
      for (size_t k = lo; k < open.size() && chains[open[k]].last_x <= p.x + reach; ++k) {
        const Chain& c = chains[open[k]];
        const double d = std::abs(c.last_x - p.x);
        if (!taken[k] && c.sign == p.sign && d <= best_d) best_d = d, best = static_cast<int>(k);
      }
      if (best >= 0) {
        taken[best] = 1;
        chains[open[best]].Add(p.x, y);
        next_open.push_back(open[best]);
      } else {
        Chain c;
        c.first_row = y;
        c.sign = p.sign;
        c.Add(p.x, y);
        chains.push_back(c);
        next_open.push_back(static_cast<int>(chains.size()) - 1);
      }
    }
    // Chains not continued stay open for one more scanned row, then close.
    for (size_t k = 0; k < open.size(); ++k) {
      if (taken[k]) continue;
      const Chain& c = chains[open[k]];
      if (y - c.last_row <= options.row_step) {
        next_open.push_back(open[k]);
      } else {
        close(c);
      }
    }
    std::sort(next_open.begin(), next_open.end(),
              [&](int a, int b) { return chains[a].last_x < chains[b].last_x; });
    open.swap(next_open);
  }
  for (int k : open) close(chains[k]);
}

}  // namespace corridor
