#include "perception/ceiling_detector.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "corridor_depth/corridor_frame.h"
#include "core/cpu_features.h"
#ifdef CORRIDOR_AVX2_VARIANTS
#include <immintrin.h>
#endif
#include "perception/corridor_projection.h"
#include "perception/oriented_edges.h"

namespace corridor {
namespace {

// The pixels of every searched line: for each height, the left then the right ceiling/wall
// junction, each as `samples` points evenly spaced in inverse distance along the corridor.
struct SearchLines {
  std::vector<double> heights;    // The searched ceiling heights, m.
  int samples = 0;                // Points per line.
  std::vector<cv::Point> pixels;  // [(height * 2 + side) * samples + i]; x = -1 where not visible.
  std::vector<double> depths;     // The points' depths along each line, m.
  int top = 0, bottom = -1;       // Rows spanned by the visible pixels (bottom < top: none).

  const cv::Point* Line(size_t height, int side) const {
    return pixels.data() + (2 * height + side) * samples;
  }
};

// Projects the points (x, y, z[i]) of one searched line of an undistorted camera, four at a time,
// into out[i] ((-1, -1) where not visible); returns how many it did (a multiple of four; the
// caller projects the rest). The same operations as ProjectCorridorPoint with a 1 px margin
// (rotation as ToCamera adds it, then f x / z + c, then cvRound's rounding to nearest even; no
// FMA), so the same pixels. *top and *bottom take in the rows of the visible ones.
using RowProjector = int (*)(const Camera&, const CorridorRotation<double>&, double, double,
                             const double*, int, cv::Point*, int* top, int* bottom);

#ifdef CORRIDOR_AVX2_VARIANTS
__attribute__((target("avx2"))) int ProjectRowAvx2(const Camera& camera,
                                                   const CorridorRotation<double>& r, double x,
                                                   double y, const double* z, int n,
                                                   cv::Point* out, int* top, int* bottom) {
  const auto& m = r.m;
  // The x and y products of each camera coordinate, added first as ToCamera adds them.
  const __m256d cx_xy = _mm256_set1_pd(m[0][0] * x + m[0][1] * y);
  const __m256d cy_xy = _mm256_set1_pd(m[1][0] * x + m[1][1] * y);
  const __m256d cz_xy = _mm256_set1_pd(m[2][0] * x + m[2][1] * y);
  const __m256d m02 = _mm256_set1_pd(m[0][2]), m12 = _mm256_set1_pd(m[1][2]);
  const __m256d m22 = _mm256_set1_pd(m[2][2]);
  const __m256d fx = _mm256_set1_pd(camera.fx), fy = _mm256_set1_pd(camera.fy);
  const __m256d ppx = _mm256_set1_pd(camera.cx), ppy = _mm256_set1_pd(camera.cy);
  const __m256d min_z = _mm256_set1_pd(0.05), unit = _mm256_set1_pd(1.0);
  const __m128i one = _mm_set1_epi32(1), zero = _mm_setzero_si128();
  const __m128i max_u = _mm_set1_epi32(camera.image_width - 1);
  const __m128i max_v = _mm_set1_epi32(camera.image_height - 1);
  // The rows of the visible points: their least and largest (INT_MAX / -1 where not visible).
  __m128i least = _mm_set1_epi32(*top), most = _mm_set1_epi32(*bottom);
  const __m128i none_high = _mm_set1_epi32(std::numeric_limits<int>::max());
  const __m128i none_low = _mm_set1_epi32(-1);
  int i = 0;
  for (; i + 4 <= n; i += 4) {
    const __m256d zw = _mm256_loadu_pd(z + i);
    const __m256d cx = _mm256_add_pd(cx_xy, _mm256_mul_pd(m02, zw));
    const __m256d cy = _mm256_add_pd(cy_xy, _mm256_mul_pd(m12, zw));
    const __m256d cz = _mm256_add_pd(cz_xy, _mm256_mul_pd(m22, zw));
    const __m256d u = _mm256_add_pd(_mm256_div_pd(_mm256_mul_pd(fx, cx), cz), ppx);
    const __m256d v = _mm256_add_pd(_mm256_div_pd(_mm256_mul_pd(fy, cy), cz), ppy);
    const __m128i ui = _mm256_cvtpd_epi32(u), vi = _mm256_cvtpd_epi32(v);
    // In front (z >= 5 cm; NaN fails) and at least 1 px inside the border (NaN and overflow
    // round to INT_MIN, which fails too).
    const __m128i front =
        _mm256_cvtpd_epi32(_mm256_and_pd(_mm256_cmp_pd(cz, min_z, _CMP_GE_OQ), unit));
    __m128i ok = _mm_cmpeq_epi32(front, one);
    ok = _mm_and_si128(ok, _mm_cmpgt_epi32(ui, zero));
    ok = _mm_and_si128(ok, _mm_cmpgt_epi32(vi, zero));
    ok = _mm_and_si128(ok, _mm_cmpgt_epi32(max_u, ui));
    ok = _mm_and_si128(ok, _mm_cmpgt_epi32(max_v, vi));
    least = _mm_min_epi32(least, _mm_blendv_epi8(none_high, vi, ok));
    most = _mm_max_epi32(most, _mm_blendv_epi8(none_low, vi, ok));
    // (u, v) pairs of the four points, (-1, -1) where not visible: cv::Point is two ints.
    static_assert(sizeof(cv::Point) == 2 * sizeof(int), "cv::Point is (x, y) ints");
    const __m128i not_seen = _mm_set1_epi32(-1);
    const __m128i pairs_lo = _mm_unpacklo_epi32(ui, vi), pairs_hi = _mm_unpackhi_epi32(ui, vi);
    const __m128i ok_lo = _mm_unpacklo_epi32(ok, ok), ok_hi = _mm_unpackhi_epi32(ok, ok);
    _mm_storeu_si128(reinterpret_cast<__m128i*>(out + i),
                     _mm_blendv_epi8(not_seen, pairs_lo, ok_lo));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(out + i + 2),
                     _mm_blendv_epi8(not_seen, pairs_hi, ok_hi));
  }
  alignas(16) int rows[2][4];
  _mm_store_si128(reinterpret_cast<__m128i*>(rows[0]), least);
  _mm_store_si128(reinterpret_cast<__m128i*>(rows[1]), most);
  for (int k = 0; k < 4; ++k) {
    *top = std::min(*top, rows[0][k]);
    *bottom = std::max(*bottom, rows[1][k]);
  }
  return i;
}
#endif

// The four-at-a-time projector for this CPU and camera, or null (every point alone).
RowProjector ChooseRowProjector(bool distorted) {
  if (distorted) return nullptr;
#ifdef CORRIDOR_AVX2_VARIANTS
  if (CpuHasAvx2()) return ProjectRowAvx2;
#endif
  return nullptr;
}

// The distances of a line's samples along the corridor: `samples` from near_distance to
// far_distance, evenly spaced in inverse distance.
void SampleDepths(const CeilingDetectorOptions& o, std::vector<double>* depths) {
  depths->resize(o.samples);
  for (int i = 0; i < o.samples; ++i) {
    const double inv = 1.0 / o.near_distance +
                       (1.0 / o.far_distance - 1.0 / o.near_distance) * i / (o.samples - 1.0);
    (*depths)[i] = 1.0 / inv;
  }
}

// The coarse search's stride in heights (options.step each), the rows of edges kept above the
// coarse lines' for the fine ones between them, and how many of the best coarse heights (by the
// sum of the two sides' supports, and by each side's) are searched around.
constexpr size_t kCoarseStride = 3;
constexpr int kFineRows = 2;
constexpr int kRefined = 8;

// The heights of the kRefined highest positive values offered, highest first (the first offered
// of equal ones first).
struct TopHeights {
  double value[kRefined];
  size_t at[kRefined];
  int size = 0;

  void Offer(double v, size_t k) {
    if (!(v > 0)) return;
    int j = size;
    while (j > 0 && v > value[j - 1]) --j;
    if (j >= kRefined) return;
    for (int m = std::min(size, kRefined - 1); m > j; --m) {
      value[m] = value[m - 1];
      at[m] = at[m - 1];
    }
    value[j] = v;
    at[j] = k;
    size = std::min(size + 1, kRefined);
  }
};

// Samples a line must count as visible at least, when judged on those in view.
int CountedSamples(const CeilingDetectorOptions& o) {
  return std::max(1, static_cast<int>(std::lround(o.min_counted_fraction * o.samples)));
}

// The searched heights, the samples' depths and the pixel buffer of `lines`; no line projected
// yet (ProjectHeight), no rows spanned.
void SetUpSearchLines(const Camera& camera, const CorridorGeometry& g,
                      const CeilingDetectorOptions& o, SearchLines* lines) {
  const double lo = std::max(o.min_height, g.camera_height + 0.1);
  lines->heights.clear();
  for (double height = lo; height <= o.max_height; height += o.step) {
    lines->heights.push_back(height);
  }
  lines->samples = o.samples;
  SampleDepths(o, &lines->depths);
  // Every projected line's points are written; the buffer keeps its memory from the thread's last
  // search.
  lines->pixels.resize(lines->heights.size() * 2 * o.samples);
  lines->top = camera.image_height;
  lines->bottom = -1;
}

// Projects the two lines of height index k into `lines`, widening its rows spanned.
void ProjectHeight(const Camera& camera, const CorridorGeometry& g,
                   const CorridorRotation<double>& r, RowProjector fast, size_t k,
                   SearchLines* lines) {
  const double wall_x[2] = {-g.LeftDistance(), g.RightDistance()};
  const bool distorted = fast == nullptr && camera.HasDistortion();
  const std::vector<double>& depths = lines->depths;
  const int samples = lines->samples;
  const double y = g.camera_height - lines->heights[k];  // Corridor Y of the ceiling (< 0).
  cv::Point* out = lines->pixels.data() + 2 * k * samples;
  for (int side = 0; side < 2; ++side, out += samples) {
    int i = 0;
    if (fast != nullptr) {
      i = fast(camera, r, wall_x[side], y, depths.data(), samples, out, &lines->top,
               &lines->bottom);
    }
    for (; i < samples; ++i) {
      cv::Point p;
      const bool seen =
          ProjectCorridorPoint(camera, distorted, r, wall_x[side], y, depths[i], 1, &p);
      out[i] = seen ? p : cv::Point(-1, -1);
      if (!seen) continue;
      lines->top = std::min(lines->top, p.y);
      lines->bottom = std::max(lines->bottom, p.y);
    }
  }
}

}  // namespace

bool CeilingDetectorOptions::Check(std::string* why) const {
  std::string reason;
  if (!(min_height > 0 && max_height > min_height && step > 0)) {
    reason = "ceiling search needs 0 < min_height < max_height and step > 0";
  } else if (!(near_distance > 0 && far_distance > near_distance) || samples < 10) {
    reason = "ceiling samples need 0 < near_distance < far_distance and >= 10 samples";
  } else if (!(min_support > 0 && min_support <= 1)) {
    reason = "min_support must be in (0, 1]";
  } else if (!(min_counted_fraction > 0 && min_counted_fraction <= 1)) {
    reason = "min_counted_fraction must be in (0, 1]";
  }
  if (reason.empty()) return true;
  if (why != nullptr) *why = reason;
  return false;
}

Status DetectCeiling(const cv::Mat& bgr, const Camera& camera, const CorridorGeometry& g,
                     const CeilingDetectorOptions& o, CeilingEstimate* estimate,
                     ImageEdges* shared) {
  *estimate = CeilingEstimate();
  std::string why;
  if (!o.Check(&why)) return Status::InvalidArgument("ceiling detector: " + why);
  if (bgr.empty() || bgr.cols != camera.image_width || bgr.rows != camera.image_height) {
    return Status::InvalidArgument("ceiling detector: image does not match the camera");
  }
  // Per thread, so that its half a megabyte of pixels is allocated once, not every search.
  thread_local SearchLines thread_lines;
  // Its address opaque to the optimiser, so that a shared object does not call __tls_get_addr at
  // each use (see OrientedHoughSegments).
  SearchLines* lines_address = &thread_lines;
  asm(""
      : "+r"(lines_address));
  SearchLines& lines = *lines_address;
  SetUpSearchLines(camera, g, o, &lines);
  const size_t count = lines.heights.size();
  if (count == 0) {
    estimate->reason = "no ceiling/wall junction follows the image's edges";
    return Status::Ok();
  }
  // Coarse to fine: every kCoarseStride-th height (and the last) first, then every height around
  // the best coarse ones; each height's two lines are projected only when it is scored. Edges are
  // computed only on the rows the coarse lines cross, with a few rows more above for the fine
  // lines between them.
  const CorridorRotation<double> r(g.pitch, g.yaw);
  const RowProjector fast = ChooseRowProjector(camera.HasDistortion());
  thread_local std::vector<uchar> thread_scored;
  std::vector<uchar>& scored = thread_scored;  // 1 where a height's lines are projected.
  scored.assign(count, 0);
  for (size_t k = 0; k < count; k += kCoarseStride) scored[k] = 1;
  scored[count - 1] = 1;
  for (size_t k = 0; k < count; ++k) {
    if (scored[k]) ProjectHeight(camera, g, r, fast, k, &lines);
  }
  if (lines.bottom < lines.top) {
    estimate->reason = "no ceiling/wall junction follows the image's edges";
    return Status::Ok();
  }
  // The lowest height's lines (coarse) are the lowest: the band's bottom, and with it how far
  // down the shared edges are computed, are those of every line.
  const OrientedEdges edges =
      ComputeOrientedEdges(bgr, lines.top - 2 - kFineRows, lines.bottom + 3, shared);
  const int band_top = edges.top, band_bottom = edges.top + edges.edges.rows;
  thread_local std::vector<LineHits> thread_hits;
  std::vector<LineHits>& all_hits = thread_hits;  // [2 k + side], where scored.
  all_hits.resize(2 * count);
  const auto score_height = [&](size_t k) {
    for (int side = 0; side < 2; ++side) {
      all_hits[2 * k + side] = OrientedLineHits(lines.Line(k, side), lines.samples, edges);
    }
  };
  const auto support = [&](size_t k, int side) {
    return all_hits[2 * k + side].Fraction(lines.samples / 2);
  };
  for (size_t k = 0; k < count; ++k) {
    if (scored[k]) score_height(k);
  }
  // Around the coarse heights with the kRefined best sums and the kRefined best supports of each
  // side: every height within a stride, projected and scored.
  TopHeights best_sums, best_sides[2];
  for (size_t k = 0; k < count; ++k) {
    if (!scored[k]) continue;
    const double left = support(k, 0), right = support(k, 1);
    best_sums.Offer(left + right, k);
    best_sides[0].Offer(left, k);
    best_sides[1].Offer(right, k);
  }
  size_t around[3 * kRefined];
  int arounds = 0;
  for (const TopHeights* top : {&best_sums, &best_sides[0], &best_sides[1]}) {
    for (int j = 0; j < top->size; ++j) around[arounds++] = top->at[j];
  }
  const auto score_new = [&](size_t k) {
    scored[k] = 1;
    const int top = lines.top, bottom = lines.bottom;  // The band is set: rows not widened.
    ProjectHeight(camera, g, r, fast, k, &lines);
    lines.top = top;
    lines.bottom = bottom;
    score_height(k);
  };
  for (int j = 0; j < arounds; ++j) {
    const size_t from = around[j] >= kCoarseStride ? around[j] - kCoarseStride + 1 : 0;
    const size_t to = std::min(count, around[j] + kCoarseStride);
    for (size_t k = from; k < to; ++k) {
      if (!scored[k]) score_new(k);
    }
  }
  // Then the neighbours of the best sum and of each side's best, until both neighbours of each
  // are scored: a best on a plateau or a slope that leaves the windows is followed along it.
  for (bool grew = true; grew;) {
    grew = false;
    size_t best_at[3] = {0, 0, 0};
    double best_value[3] = {0, 0, 0};
    for (size_t k = 0; k < count; ++k) {
      if (!scored[k]) continue;
      const double left = support(k, 0), right = support(k, 1);
      const double values[3] = {left + right, left, right};
      for (int c = 0; c < 3; ++c) {
        if (values[c] > best_value[c]) best_value[c] = values[c], best_at[c] = k;
      }
    }
    for (int c = 0; c < 3; ++c) {
      if (!(best_value[c] > 0)) continue;
      for (const size_t k : {best_at[c] - 1, best_at[c] + 1}) {
        if (k >= count || scored[k]) continue;  // best_at - 1 wraps past count at 0.
        score_new(k);
        grew = true;
      }
    }
  }

  // The best height of those scored, as if every height had been: the first of the highest sum,
  // and each side's first of its highest support.
  double best_score = 0;
  size_t best = 0;
  LineHits best_hits[2], side_hits[2];
  for (size_t k = 0; k < count; ++k) {
    if (!scored[k]) continue;
    const double sides[2] = {support(k, 0), support(k, 1)};
    for (int side = 0; side < 2; ++side) {
      if (sides[side] > estimate->side_support[side]) {
        estimate->side_support[side] = sides[side];
        estimate->side_height[side] = lines.heights[k];
        side_hits[side] = all_hits[2 * k + side];
      }
    }
    const double score = sides[0] + sides[1];
    if (score > best_score) {
      best_score = score;
      best = k;
      best_hits[0] = all_hits[2 * k];
      best_hits[1] = all_hits[2 * k + 1];
    }
  }
  // The search above compares heights by the fraction of at least half the samples; whether the
  // chosen lines are there is judged on the samples in view (at least min_counted_fraction).
  const int counted = CountedSamples(o);
  const double best_left = best_hits[0].Fraction(counted);
  const double best_right = best_hits[1].Fraction(counted);
  for (int side = 0; side < 2; ++side) {
    estimate->side_visible_support[side] = side_hits[side].Fraction(counted);
  }
  estimate->left_support = best_left;
  estimate->right_support = best_right;
  if (std::max(best_left, best_right) < o.min_support) {
    estimate->reason = "no ceiling/wall junction follows the image's edges";
    return Status::Ok();
  }
  // Refine: every edge pixel within 2 px of an accepted line gives H_c from its ray and wall.
  const double h = g.camera_height;
  // In the thread's buffer, which keeps its memory from search to search.
  thread_local std::vector<double> thread_heights;
  std::vector<double>& heights = thread_heights;
  heights.clear();
  heights.reserve(static_cast<size_t>(10) * lines.samples);  // Two sides, five rows a sample.
  const Vec3<double> n = r.FloorNormal(), m = r.WallNormal();
  for (int side = 0; side < 2; ++side) {
    if ((side == 0 ? best_left : best_right) < o.min_support) continue;
    const double wall_x = side == 0 ? -g.LeftDistance() : g.RightDistance();
    const cv::Point* line = lines.Line(best, side);
    for (int i = 0; i < lines.samples; ++i) {
      const cv::Point p = line[i];
      if (p.x < 0) continue;
      for (int dv = -2; dv <= 2; ++dv) {
        const int v = p.y + dv;
        if (v < band_top || v >= band_bottom) continue;
        if (edges.edges.at<uchar>(v - band_top, p.x) == 0) continue;
        const Vec3<double> ray = RayOfRawPixel(camera, p.x, v);
        const double mr = Dot(m, ray);
        if (std::abs(mr) < 1e-9) continue;
        const double z = wall_x / mr;  // The ray meets its wall plane X = wall_x at depth z.
        if (z <= 0) continue;
        heights.push_back(h - z * Dot(n, ray));  // H_c = h - Y_W.
      }
    }
  }
  if (heights.size() < 5) {
    estimate->reason = "too few edge pixels on the ceiling/wall junctions";
    return Status::Ok();
  }
  std::nth_element(heights.begin(), heights.begin() + heights.size() / 2, heights.end());
  estimate->height = heights[heights.size() / 2];
  estimate->points = static_cast<int>(heights.size());
  estimate->found = estimate->height > h;
  if (!estimate->found) estimate->reason = "the ceiling estimate lies below the camera";
  return Status::Ok();
}

std::vector<double> CorridorLinesSupport(const cv::Mat& bgr, const Camera& camera,
                                         const CorridorGeometry& g, const std::vector<double>& xs,
                                         double y, const CeilingDetectorOptions& o,
                                         ImageEdges* edges) {
  std::vector<double> supports(xs.size(), 0.0);
  if (bgr.empty() || xs.empty() || !o.Check(nullptr)) return supports;
  const CorridorRotation<double> r(g.pitch, g.yaw);
  const bool distorted = camera.HasDistortion();
  std::vector<double> depths;
  SampleDepths(o, &depths);
  std::vector<cv::Point> lines(xs.size() * o.samples, cv::Point(-1, -1));
  int top = camera.image_height, bottom = -1;
  for (size_t k = 0; k < xs.size(); ++k) {
    for (int i = 0; i < o.samples; ++i) {
      cv::Point p;
      if (!ProjectCorridorPoint(camera, distorted, r, xs[k], y, depths[i], 1, &p)) continue;
      lines[k * o.samples + i] = p;
      top = std::min(top, p.y);
      bottom = std::max(bottom, p.y);
    }
  }
  if (bottom < top) return supports;
  // One band over all the lines' rows: each line's pixels lie inside it with the margins a band
  // of its own would give them, so each gets the same hits.
  const OrientedEdges band = ComputeOrientedEdges(bgr, top - 2, bottom + 3, edges);
  for (size_t k = 0; k < xs.size(); ++k) {
    supports[k] = OrientedLineHits(lines.data() + k * o.samples, o.samples, band)
                      .Fraction(CountedSamples(o));
  }
  return supports;
}

double CorridorLineSupport(const cv::Mat& bgr, const Camera& camera, const CorridorGeometry& g,
                           double x, double y, const CeilingDetectorOptions& o, ImageEdges* edges) {
  return CorridorLinesSupport(bgr, camera, g, {x}, y, o, edges).front();
}

double BestFloorLineSupportNear(const cv::Mat& bgr, const Camera& camera,
                                const CorridorGeometry& g, double x, double spread,
                                const CeilingDetectorOptions& options, ImageEdges* edges) {
  std::vector<double> xs;
  for (double r = 1 / spread; r <= spread + 1e-9; r += 0.01) xs.push_back(x * r);
  const std::vector<double> supports =
      CorridorLinesSupport(bgr, camera, g, xs, g.camera_height, options, edges);
  return supports.empty() ? 0 : *std::max_element(supports.begin(), supports.end());
}

}  // namespace corridor
