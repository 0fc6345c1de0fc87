#include "perception/robust_line_fit.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/cpu_features.h"

#ifdef CORRIDOR_AVX2_VARIANTS
#include <immintrin.h>
#endif

namespace corridor {
namespace {

constexpr double kHuber = 1.345, kMinDistance = 0.05;
constexpr int kMaxIterations = 60;
constexpr int kLanes = 4;  // Points a step: partial sums in four lanes, added at the end.

// Weighted sums of the points about an anchor (the first point, against cancellation), and the
// sum of their distances to the line they were weighted by.
struct Sums {
  double distance = 0, w = 0, u = 0, v = 0, uu = 0, uv = 0, vv = 0;

  // The total least squares line of the sums, normalised with b >= 0.
  Eigen::Vector3d Line(const Eigen::Vector2d& anchor) const {
    const double mu = u / w, mv = v / w;
    const double cuu = uu / w - mu * mu, cuv = uv / w - mu * mv, cvv = vv / w - mv * mv;
    // Direction of the largest spread; the normal is perpendicular to it.
    const double angle = 0.5 * std::atan2(2 * cuv, cuu - cvv);
    Eigen::Vector3d l(-std::sin(angle), std::cos(angle), 0);
    l.z() = -(l.x() * (mu + anchor.x()) + l.y() * (mv + anchor.y()));
    if (l.y() < 0) l = -l;
    return l;
  }
};

// The points as columns: u, v about the anchor.
struct Columns {
  std::vector<double> u, v;
};

// Weight of a point at distance d: 1 (the unweighted fit), Huber's, or L1's.
enum class Weight { kOne,
                    kHuberWeight,
                    kL1 };

template <Weight kWeight>
inline double WeightOf(double d) {
  if (kWeight == Weight::kOne) return 1.0;
  if (kWeight == Weight::kHuberWeight) return d < kHuber ? 1.0 : kHuber / d;
  return 1.0 / std::max(d, kMinDistance);
}

// Partial sums in kLanes lanes: point i goes to lane i % kLanes.
struct Lanes {
  std::array<double, kLanes> d{}, w{}, u{}, v{}, uu{}, uv{}, vv{};

  // Adds the point (pu, pv) to lane k: its distance to the line a u + b v + c = 0 and weight.
  template <Weight kWeight>
  void Add(int k, double pu, double pv, double a, double b, double c) {
    const double distance = std::abs(a * pu + b * pv + c);
    const double weight = WeightOf<kWeight>(distance);
    const double wu = weight * pu, wv = weight * pv;
    d[k] += distance;
    w[k] += weight;
    u[k] += wu;
    v[k] += wv;
    uu[k] += wu * pu;
    uv[k] += wu * pv;
    vv[k] += wv * pv;
  }

  // The lanes added, lane 0 first.
  Sums Total() const {
    Sums s;
    for (int k = 0; k < kLanes; ++k) {
      s.distance += d[k];
      s.w += w[k];
      s.u += u[k];
      s.v += v[k];
      s.uu += uu[k];
      s.uv += uv[k];
      s.vv += vv[k];
    }
    return s;
  }
};

// One pass: distances to the line a u + b v + c = 0 (about the anchor) and the weighted sums.
template <Weight kWeight>
Sums Pass(const double* u, const double* v, int n, double a, double b, double c) {
  Lanes lanes;
  for (int i = 0; i < n; ++i) lanes.Add<kWeight>(i % kLanes, u[i], v[i], a, b, c);
  return lanes.Total();
}

#ifdef CORRIDOR_AVX2_VARIANTS
// The same pass in AVX2 registers, a point a lane, operation for operation the scalar one's (no
// FMA), so that both give the same sums.
template <Weight kWeight>
__attribute__((target("avx2"))) Sums PassAvx2(const double* u, const double* v, int n, double a,
                                              double b, double c) {
  const __m256d va = _mm256_set1_pd(a), vb = _mm256_set1_pd(b), vc = _mm256_set1_pd(c);
  const __m256d sign = _mm256_set1_pd(-0.0), one = _mm256_set1_pd(1.0);
  const __m256d huber = _mm256_set1_pd(kHuber), least = _mm256_set1_pd(kMinDistance);
  __m256d sd = _mm256_setzero_pd(), sw = sd, su = sd, sv = sd, suu = sd, suv = sd, svv = sd;
  int i = 0;
  for (; i + kLanes <= n; i += kLanes) {
    const __m256d pu = _mm256_loadu_pd(u + i), pv = _mm256_loadu_pd(v + i);
    const __m256d d = _mm256_andnot_pd(
        sign, _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(va, pu), _mm256_mul_pd(vb, pv)), vc));
    __m256d w = one;
    if (kWeight == Weight::kHuberWeight) {
      w = _mm256_blendv_pd(_mm256_div_pd(huber, d), one, _mm256_cmp_pd(d, huber, _CMP_LT_OQ));
    } else if (kWeight == Weight::kL1) {
      w = _mm256_div_pd(one, _mm256_max_pd(least, d));  // max(least, d) is std::max(d, least).
    }
    const __m256d wu = _mm256_mul_pd(w, pu), wv = _mm256_mul_pd(w, pv);
    sd = _mm256_add_pd(sd, d);
    sw = _mm256_add_pd(sw, w);
    su = _mm256_add_pd(su, wu);
    sv = _mm256_add_pd(sv, wv);
    suu = _mm256_add_pd(suu, _mm256_mul_pd(wu, pu));
    suv = _mm256_add_pd(suv, _mm256_mul_pd(wu, pv));
    svv = _mm256_add_pd(svv, _mm256_mul_pd(wv, pv));
  }
  Lanes lanes;
  _mm256_storeu_pd(lanes.d.data(), sd);
  _mm256_storeu_pd(lanes.w.data(), sw);
  _mm256_storeu_pd(lanes.u.data(), su);
  _mm256_storeu_pd(lanes.v.data(), sv);
  _mm256_storeu_pd(lanes.uu.data(), suu);
  _mm256_storeu_pd(lanes.uv.data(), suv);
  _mm256_storeu_pd(lanes.vv.data(), svv);
  for (; i < n; ++i) lanes.Add<kWeight>(i % kLanes, u[i], v[i], a, b, c);
  return lanes.Total();
}
#endif

using PassFn = Sums (*)(const double*, const double*, int, double, double, double);

struct Passes {
  PassFn one = Pass<Weight::kOne>, huber = Pass<Weight::kHuberWeight>, l1 = Pass<Weight::kL1>;
};

Passes ChoosePasses() {
  Passes p;
#ifdef CORRIDOR_AVX2_VARIANTS
  if (CpuHasAvx2()) {
    p.one = PassAvx2<Weight::kOne>;
    p.huber = PassAvx2<Weight::kHuberWeight>;
    p.l1 = PassAvx2<Weight::kL1>;
  }
#endif
  return p;
}

}  // namespace

bool FitLineLeastDistance(const std::vector<Eigen::Vector2d>& points, Eigen::Vector3d* line) {
  if (points.size() < 8) return false;
  static const Passes passes = ChoosePasses();
  const Eigen::Vector2d anchor = points.front();
  // The thread's columns, which keep their memory from call to call.
  thread_local Columns thread_columns;
  Columns& c = thread_columns;
  c.u.clear();
  c.v.clear();
  for (const auto& p : points) {
    c.u.push_back(p.x() - anchor.x());
    c.v.push_back(p.y() - anchor.y());
  }
  const int n = static_cast<int>(points.size());
  // The line about the anchor: a u + b v + c' = 0 with c' = c + a x0 + b y0.
  const auto pass = [&](PassFn fn, const Eigen::Vector3d& l) {
    return fn(c.u.data(), c.v.data(), n, l.x(), l.y(),
              l.z() + l.x() * anchor.x() + l.y() * anchor.y());
  };
  Eigen::Vector3d l = pass(passes.one, Eigen::Vector3d(0, 1, -anchor.y())).Line(anchor);
  Eigen::Vector3d best = l;
  double best_sum = 1e300;
  bool l1 = false;  // Huber weights until they converge, then L1 weights.
  for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
    const Sums sums = pass(l1 ? passes.l1 : passes.huber, l);
    if (sums.distance < best_sum) {
      best_sum = sums.distance;
      best = l;
    }
    const Eigen::Vector3d next = sums.Line(anchor);
    const bool converged = (next - l).cwiseAbs().maxCoeff() < 1e-6;
    l = next;
    if (converged && l1) break;
    if (converged) l1 = true;
  }
  if (!best.allFinite()) return false;
  *line = best;
  return true;
}

}  // namespace corridor
