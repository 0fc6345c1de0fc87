#include "estimation/side_moments.h"

#include <cmath>
#include <limits>

#include "core/cpu_features.h"
#include "estimation/bounded_lm.h"

#ifdef CORRIDOR_AVX2_VARIANTS
#include <immintrin.h>
#endif

namespace corridor {
namespace {

constexpr int kLanes = 4;  // Points a step: partial sums in four lanes, added at the end.

// The moments' partial sums: point i goes to lane i % kLanes.
struct Lanes {
  double a00[kLanes] = {}, a01[kLanes] = {}, a02[kLanes] = {}, a11[kLanes] = {};
  double a12[kLanes] = {}, a22[kLanes] = {}, b0[kLanes] = {}, b1[kLanes] = {}, b2[kLanes] = {};

  // Adds the point p = (pu, pv, 1) with its Jacobian factor q and corrected residual f to lane k.
  void Add(int k, double pu, double pv, double q, double f) {
    const double qq = q * q, qf = q * f;
    a00[k] += qq * pu * pu;
    a01[k] += qq * pu * pv;
    a02[k] += qq * pu;
    a11[k] += qq * pv * pv;
    a12[k] += qq * pv;
    a22[k] += qq;
    b0[k] += qf * pu;
    b1[k] += qf * pv;
    b2[k] += qf;
  }

  // The lanes added, lane 0 first.
  SideMoments Total() const {
    SideMoments m;
    for (int k = 0; k < kLanes; ++k) {
      m.a[0][0] += a00[k];
      m.a[0][1] += a01[k];
      m.a[0][2] += a02[k];
      m.a[1][1] += a11[k];
      m.a[1][2] += a12[k];
      m.a[2][2] += a22[k];
      m.b[0] += b0[k];
      m.b[1] += b1[k];
      m.b[2] += b2[k];
    }
    m.a[1][0] = m.a[0][1];
    m.a[2][0] = m.a[0][2];
    m.a[2][1] = m.a[1][2];
    return m;
  }
};

// Points [begin, end): their costs into *cost and moments into *lanes; false at a residual that
// is not finite.
bool AccumulateScalar(const FloorIntrinsics& intrinsics, const RobustLoss& loss,
                      const double line[3], const std::vector<Eigen::Vector2d>& points,
                      const std::vector<double>& weights, size_t begin, double* cost,
                      Lanes* lanes) {
  for (size_t i = begin; i < points.size(); ++i) {
    // As JunctionLineResidual::Distance computes it (times 1.0 without weights: the same value).
    const double pu = (points[i].x() - intrinsics.cx) / intrinsics.fx;
    const double pv = (points[i].y() - intrinsics.cy) / intrinsics.fy;
    const double root_weight = weights.empty() ? 1.0 : std::sqrt(weights[i]);
    const double residual = (line[0] * pu + line[1] * pv + line[2]) * root_weight;
    if (!std::isfinite(residual)) return false;
    double term = 0, residual_scale = 1, jacobian_scale = 1;
    bounded_lm::Correct(loss, residual, &term, &residual_scale, &jacobian_scale);
    *cost += term;
    lanes->Add(static_cast<int>(i % kLanes), pu, pv, jacobian_scale * root_weight,
               residual * residual_scale);
  }
  return true;
}

#ifdef CORRIDOR_AVX2_VARIANTS
// AccumulateScalar's loop, a point a lane, over the first whole groups of kLanes points, for no
// loss or Huber's (bounded_lm::Correct's operations: for these losses rho'' <= 0, so both factors
// are sqrt(rho')); *done gets the number of points taken.
__attribute__((target("avx2"))) bool AccumulateAvx2(
    const FloorIntrinsics& intrinsics, const RobustLoss& loss, const double line[3],
    const std::vector<Eigen::Vector2d>& points, const std::vector<double>& weights,
    double* cost, Lanes* lanes, size_t* done) {
  const __m256d cx = _mm256_set1_pd(intrinsics.cx), cy = _mm256_set1_pd(intrinsics.cy);
  const __m256d fx = _mm256_set1_pd(intrinsics.fx), fy = _mm256_set1_pd(intrinsics.fy);
  const __m256d l0 = _mm256_set1_pd(line[0]), l1 = _mm256_set1_pd(line[1]);
  const __m256d l2 = _mm256_set1_pd(line[2]);
  const __m256d one = _mm256_set1_pd(1.0), half = _mm256_set1_pd(0.5);
  const __m256d sign = _mm256_set1_pd(-0.0);
  const __m256d infinity = _mm256_set1_pd(std::numeric_limits<double>::infinity());
  const __m256d smallest = _mm256_set1_pd(std::numeric_limits<double>::min());
  const bool huber = loss.kind() == RobustLoss::Kind::kHuber;
  const __m256d a = _mm256_set1_pd(loss.scale()), b = _mm256_set1_pd(loss.scale_sq());
  const __m256d two_a = _mm256_set1_pd(2.0 * loss.scale());
  __m256d s00 = _mm256_setzero_pd(), s01 = s00, s02 = s00, s11 = s00, s12 = s00, s22 = s00;
  __m256d t0 = s00, t1 = s00, t2 = s00;
  const double* xy = points.empty() ? nullptr : points.front().data();
  const size_t n = points.size() - points.size() % kLanes;
  for (size_t i = 0; i < n; i += kLanes) {
    // x0 y0 x1 y1 | x2 y2 x3 y3 -> x0 x2 x1 x3 -> x0 x1 x2 x3 (and y).
    const __m256d p01 = _mm256_loadu_pd(xy + 2 * i), p23 = _mm256_loadu_pd(xy + 2 * i + 4);
    const __m256d x = _mm256_permute4x64_pd(_mm256_unpacklo_pd(p01, p23), 0xD8);
    const __m256d y = _mm256_permute4x64_pd(_mm256_unpackhi_pd(p01, p23), 0xD8);
    const __m256d pu = _mm256_div_pd(_mm256_sub_pd(x, cx), fx);
    const __m256d pv = _mm256_div_pd(_mm256_sub_pd(y, cy), fy);
    const __m256d root_weight =
        weights.empty() ? one : _mm256_sqrt_pd(_mm256_loadu_pd(weights.data() + i));
    const __m256d residual = _mm256_mul_pd(
        _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(l0, pu), _mm256_mul_pd(l1, pv)), l2),
        root_weight);
    const __m256d magnitude = _mm256_andnot_pd(sign, residual);
    if (_mm256_movemask_pd(_mm256_cmp_pd(magnitude, infinity, _CMP_LT_OQ)) != 0xF) return false;
    const __m256d s = _mm256_mul_pd(residual, residual);
    __m256d rho0 = s, scale = one;
    if (huber) {
      // Beyond the scale: rho = 2 a sqrt(s) - b, rho' = max(smallest, a / sqrt(s)).
      const __m256d beyond = _mm256_cmp_pd(s, b, _CMP_GT_OQ);
      const __m256d root = _mm256_sqrt_pd(s);
      const __m256d outer = _mm256_sub_pd(_mm256_mul_pd(two_a, root), b);
      const __m256d slope = _mm256_max_pd(_mm256_div_pd(a, root), smallest);
      rho0 = _mm256_blendv_pd(s, outer, beyond);
      scale = _mm256_blendv_pd(one, _mm256_sqrt_pd(slope), beyond);
    }
    alignas(32) double terms[kLanes];
    _mm256_store_pd(terms, _mm256_mul_pd(half, rho0));
    for (int k = 0; k < kLanes; ++k) *cost += terms[k];
    const __m256d q = _mm256_mul_pd(scale, root_weight);
    const __m256d f = _mm256_mul_pd(residual, scale);
    const __m256d qq = _mm256_mul_pd(q, q), qf = _mm256_mul_pd(q, f);
    const __m256d qq_pu = _mm256_mul_pd(qq, pu), qq_pv = _mm256_mul_pd(qq, pv);
    s00 = _mm256_add_pd(s00, _mm256_mul_pd(qq_pu, pu));
    s01 = _mm256_add_pd(s01, _mm256_mul_pd(qq_pu, pv));
    s02 = _mm256_add_pd(s02, qq_pu);
    s11 = _mm256_add_pd(s11, _mm256_mul_pd(qq_pv, pv));
    s12 = _mm256_add_pd(s12, qq_pv);
    s22 = _mm256_add_pd(s22, qq);
    t0 = _mm256_add_pd(t0, _mm256_mul_pd(qf, pu));
    t1 = _mm256_add_pd(t1, _mm256_mul_pd(qf, pv));
    t2 = _mm256_add_pd(t2, qf);
  }
  _mm256_storeu_pd(lanes->a00, s00);
  _mm256_storeu_pd(lanes->a01, s01);
  _mm256_storeu_pd(lanes->a02, s02);
  _mm256_storeu_pd(lanes->a11, s11);
  _mm256_storeu_pd(lanes->a12, s12);
  _mm256_storeu_pd(lanes->a22, s22);
  _mm256_storeu_pd(lanes->b0, t0);
  _mm256_storeu_pd(lanes->b1, t1);
  _mm256_storeu_pd(lanes->b2, t2);
  *done = n;
  return true;
}
#endif

}  // namespace

bool AccumulateSideMoments(const FloorIntrinsics& intrinsics, const RobustLoss& loss,
                           const double line[3], const std::vector<Eigen::Vector2d>& points,
                           const std::vector<double>& weights, double* cost,
                           SideMoments* moments) {
  Lanes lanes;
  size_t done = 0;
#ifdef CORRIDOR_AVX2_VARIANTS
  static const bool avx2 = CpuHasAvx2();
  if (avx2 && loss.kind() != RobustLoss::Kind::kCauchy &&
      !AccumulateAvx2(intrinsics, loss, line, points, weights, cost, &lanes, &done)) {
    return false;
  }
#endif
  if (!AccumulateScalar(intrinsics, loss, line, points, weights, done, cost, &lanes)) {
    return false;
  }
  *moments = lanes.Total();
  return true;
}

}  // namespace corridor
