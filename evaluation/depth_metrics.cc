#include "corridor_depth/depth_metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace corridor {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Running sums over the pixels that have both ground truth and a prediction.
struct Sums {
  double abs_rel = 0, sq_rel = 0, sq = 0, sq_log = 0, sq_log10 = 0, abs_log10 = 0;
  int64_t delta[3] = {0, 0, 0};
};

void SetErrorsNaN(DepthMetrics* m) {
  m->abs_rel = m->sq_rel = m->rmse = m->rmse_log = m->rmse_log10 = m->log10 = kNaN;
  m->delta1 = m->delta2 = m->delta3 = kNaN;
}

void Accumulate(double gt, double pred, Sums* s) {
  const double diff = gt - pred;
  const double dlog = std::log(gt) - std::log(pred);
  const double dlog10 = std::log10(gt) - std::log10(pred);
  s->abs_rel += std::abs(diff) / gt;
  s->sq_rel += diff * diff / gt;
  s->sq += diff * diff;
  s->sq_log += dlog * dlog;
  s->sq_log10 += dlog10 * dlog10;
  s->abs_log10 += std::abs(dlog10);
  const double ratio = std::max(gt / pred, pred / gt);
  // 1.25, 1.25^2 and 1.25^3 are exact in binary.
  if (ratio < 1.25) ++s->delta[0];
  if (ratio < 1.25 * 1.25) ++s->delta[1];
  if (ratio < 1.25 * 1.25 * 1.25) ++s->delta[2];
}

// Mean of one field over the records where it is not NaN; NaN when there is none.
template <typename Getter>
double MeanOf(const std::vector<DepthMetrics>& records, Getter get) {
  double sum = 0;
  int count = 0;
  for (const DepthMetrics& m : records) {
    const double v = get(m);
    if (std::isnan(v)) continue;
    sum += v;
    ++count;
  }
  return count > 0 ? sum / count : kNaN;
}

}  // namespace

DepthMetrics ComputeDepthMetrics(const cv::Mat& pred, const cv::Mat& gt, double cap) {
  DepthMetrics m;
  SetErrorsNaN(&m);
  m.coverage = kNaN;
  if (pred.size() != gt.size() || pred.type() != CV_32FC1 || gt.type() != CV_32FC1) {
    return m;  // A caller's mistake: nothing is evaluated, every field NaN.
  }
  Sums s;
  for (int r = 0; r < gt.rows; ++r) {
    const float* g_row = gt.ptr<float>(r);
    const float* p_row = pred.ptr<float>(r);
    for (int c = 0; c < gt.cols; ++c) {
      const double g = g_row[c], p = p_row[c];
      if (!std::isfinite(g) || !(g > 0) || !(g <= cap)) continue;
      ++m.num_gt;
      if (!std::isfinite(p) || !(p > 0)) continue;
      ++m.num_evaluated;
      Accumulate(g, p, &s);
    }
  }
  if (m.num_gt == 0) return m;
  m.coverage = static_cast<double>(m.num_evaluated) / static_cast<double>(m.num_gt);
  if (m.num_evaluated == 0) return m;
  const double n = static_cast<double>(m.num_evaluated);
  m.abs_rel = s.abs_rel / n;
  m.sq_rel = s.sq_rel / n;
  m.rmse = std::sqrt(s.sq / n);
  m.rmse_log = std::sqrt(s.sq_log / n);
  m.rmse_log10 = std::sqrt(s.sq_log10 / n);
  m.log10 = s.abs_log10 / n;
  m.delta1 = static_cast<double>(s.delta[0]) / n;
  m.delta2 = static_cast<double>(s.delta[1]) / n;
  m.delta3 = static_cast<double>(s.delta[2]) / n;
  return m;
}

DepthMetrics AverageDepthMetrics(const std::vector<DepthMetrics>& per_image) {
  DepthMetrics m;
  m.abs_rel = MeanOf(per_image, [](const DepthMetrics& x) { return x.abs_rel; });
  m.sq_rel = MeanOf(per_image, [](const DepthMetrics& x) { return x.sq_rel; });
  m.rmse = MeanOf(per_image, [](const DepthMetrics& x) { return x.rmse; });
  m.rmse_log = MeanOf(per_image, [](const DepthMetrics& x) { return x.rmse_log; });
  m.rmse_log10 = MeanOf(per_image, [](const DepthMetrics& x) { return x.rmse_log10; });
  m.log10 = MeanOf(per_image, [](const DepthMetrics& x) { return x.log10; });
  m.delta1 = MeanOf(per_image, [](const DepthMetrics& x) { return x.delta1; });
  m.delta2 = MeanOf(per_image, [](const DepthMetrics& x) { return x.delta2; });
  m.delta3 = MeanOf(per_image, [](const DepthMetrics& x) { return x.delta3; });
  // Images without ground truth have NaN coverage and drop out; with gt but no
  // prediction they have coverage 0 and count.
  m.coverage = MeanOf(per_image, [](const DepthMetrics& x) { return x.coverage; });
  m.num_gt = 0;
  m.num_evaluated = 0;
  for (const DepthMetrics& x : per_image) {
    m.num_gt += x.num_gt;
    m.num_evaluated += x.num_evaluated;
  }
  m.num_images = static_cast<int>(per_image.size());
  return m;
}

double RelativeError(double estimated, double truth) {
  if (!std::isfinite(truth) || !(truth > 0)) return kNaN;
  return std::abs(estimated - truth) / truth;
}

}  // namespace corridor
