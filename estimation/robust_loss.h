#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace corridor {

// The robust losses "none", "huber" and "cauchy" of scale a, as functions rho(s) of the squared
// residual s with their first two derivatives, the way ceres::HuberLoss and ceres::CauchyLoss
// define them (rho' is kept above the smallest positive double).
class RobustLoss {
 public:
  enum class Kind {
    kNone,
    kHuber,
    kCauchy,
  };

  RobustLoss() = default;
  RobustLoss(Kind kind, double scale) : kind_(kind), a_(scale), b_(scale * scale) {}
  // "huber" and "cauchy" by name; any other name is no loss (SolverOptions::Check rejects them).
  static RobustLoss FromName(const std::string& name, double scale) {
    if (name == "huber") return RobustLoss(Kind::kHuber, scale);
    if (name == "cauchy") return RobustLoss(Kind::kCauchy, scale);
    return RobustLoss();
  }

  Kind kind() const { return kind_; }
  double scale() const { return a_; }
  double scale_sq() const { return b_; }  // scale() squared, as Evaluate uses it.

  void Evaluate(double s, double rho[3]) const {
    constexpr double kMin = std::numeric_limits<double>::min();
    switch (kind_) {
      case Kind::kHuber:
        if (s > b_) {
          const double r = std::sqrt(s);
          rho[0] = 2.0 * a_ * r - b_;
          rho[1] = std::max(kMin, a_ / r);
          rho[2] = -rho[1] / (2.0 * s);
        } else {
          rho[0] = s;
          rho[1] = 1.0;
          rho[2] = 0.0;
        }
        return;
      case Kind::kCauchy: {
        const double c = 1.0 / b_, sum = 1.0 + s * c, inv = 1.0 / sum;
        rho[0] = b_ * std::log(sum);
        rho[1] = std::max(kMin, inv);
        rho[2] = -c * (inv * inv);
        return;
      }
      case Kind::kNone:
        rho[0] = s;
        rho[1] = 1.0;
        rho[2] = 0.0;
        return;
    }
  }

 private:
  Kind kind_ = Kind::kNone;
  double a_ = 1.0, b_ = 1.0;  // scale and its square
};

}  // namespace corridor
