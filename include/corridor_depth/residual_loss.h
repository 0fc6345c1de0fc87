#pragma once

// A robust loss applied inside the stage functors, residual by residual. Ceres applies a
// LossFunction to a whole residual block, and each stage functor is one block (the symmetry
// residual couples its points through the fitted opposite line), so the functors transform each
// residual instead: r' = sign(r) sqrt(rho(r^2)), whence sum r'^2 = sum rho(r^2). The grid search
// and Levenberg-Marquardt then minimise the same robust cost.

#include <cmath>
#include <string>

namespace corridor {

struct ResidualLoss {
  enum class Kind { kNone,
                    kHuber,
                    kCauchy };
  Kind kind = Kind::kNone;  // Which rho.
  double scale = 1.0;       // a: residuals below it (pixels) count as in least squares.

  // Parses "none", "huber" or "cauchy"; false for anything else.
  static bool FromName(const std::string& name, double scale, ResidualLoss* loss);

  template <typename T>
  T Apply(const T& r) const {
    using std::abs;
    using std::log;
    using std::sqrt;
    const T sign = r < T(0.0) ? T(-1.0) : T(1.0);
    switch (kind) {
      case Kind::kNone:
        return r;
      case Kind::kHuber:
        if (abs(r) <= T(scale)) return r;
        return sign * sqrt(T(2.0 * scale) * abs(r) - T(scale * scale));
      case Kind::kCauchy:
        return sign * T(scale) * sqrt(log(T(1.0) + r * r / T(scale * scale)));
    }
    return r;
  }
};

inline bool ResidualLoss::FromName(const std::string& name, double scale, ResidualLoss* loss) {
  if (name == "none") {
    loss->kind = Kind::kNone;
  } else if (name == "huber") {
    loss->kind = Kind::kHuber;
  } else if (name == "cauchy") {
    loss->kind = Kind::kCauchy;
  } else {
    return false;
  }
  loss->scale = scale;
  return true;
}

}  // namespace corridor
