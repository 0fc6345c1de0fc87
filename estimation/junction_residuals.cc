#include "estimation/junction_residuals.h"

#include <cmath>
#include <vector>

namespace corridor {
namespace {

// One side's moments of its points p = ((u - cx) / fx, (v - cy) / fy, 1): a = sum q^2 p p' (upper
// triangle) and b = sum q f p, with q the factor of p' dl/dx in a point's Jacobian row and f its
// corrected residual.
struct SideMoments {
  double a[3][3] = {};
  double b[3] = {};
};

// Adds one side's residual costs to *cost and its moments to *moments; false when a residual is
// not finite. `line` is the side's ScaledLine at x.
bool AccumulateSide(const FloorIntrinsics& intrinsics, const RobustLoss& loss, const double* line,
                    const std::vector<Eigen::Vector2d>& points,
                    const std::vector<double>& weights, double* cost, SideMoments* moments) {
  double a00 = 0, a01 = 0, a02 = 0, a11 = 0, a12 = 0, a22 = 0, b0 = 0, b1 = 0, b2 = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    // As JunctionLineResidual::Distance computes it, so the residual is the Jet path's value.
    const double pu = (points[i].x() - intrinsics.cx) / intrinsics.fx;
    const double pv = (points[i].y() - intrinsics.cy) / intrinsics.fy;
    double residual = line[0] * pu + line[1] * pv + line[2];
    double root_weight = 1.0;
    if (!weights.empty()) {
      root_weight = std::sqrt(weights[i]);
      residual *= root_weight;
    }
    if (!std::isfinite(residual)) return false;
    double term = 0, residual_scale = 1, jacobian_scale = 1;
    bounded_lm::Correct(loss, residual, &term, &residual_scale, &jacobian_scale);
    *cost += term;
    const double q = jacobian_scale * root_weight, qq = q * q;
    const double qf = q * (residual * residual_scale);
    a00 += qq * pu * pu;
    a01 += qq * pu * pv;
    a02 += qq * pu;
    a11 += qq * pv * pv;
    a12 += qq * pv;
    a22 += qq;
    b0 += qf * pu;
    b1 += qf * pv;
    b2 += qf;
  }
  moments->a[0][0] = a00;
  moments->a[0][1] = moments->a[1][0] = a01;
  moments->a[0][2] = moments->a[2][0] = a02;
  moments->a[1][1] = a11;
  moments->a[1][2] = moments->a[2][1] = a12;
  moments->a[2][2] = a22;
  moments->b[0] = b0;
  moments->b[1] = b1;
  moments->b[2] = b2;
  return true;
}

}  // namespace

bool JunctionResiduals::Linearize(const RobustLoss& loss, const double* x,
                                  bounded_lm::Linearization<4>* lin) const {
  Jet xj[4];
  for (int k = 0; k < 4; ++k) xj[k] = Jet(x[k], k);
  if (!Prepare(static_cast<const Jet*>(xj))) return false;
  double normal[4][5] = {};  // [J'J | J'f]
  for (int side = 0; side < 2; ++side) {
    const std::vector<Eigen::Vector2d>& points = side == 0 ? observation_.left : observation_.right;
    if (points.empty()) continue;
    const Vec3<Jet>& line = jet_lines_[side];
    const double value[3] = {line.x.a, line.y.a, line.z.a};
    // d[c][k]: the derivative of the line's entry c by x_k.
    double d[3][4];
    for (int k = 0; k < 4; ++k) {
      d[0][k] = line.x.v[k];
      d[1][k] = line.y.v[k];
      d[2][k] = line.z.v[k];
      if (!std::isfinite(d[0][k]) || !std::isfinite(d[1][k]) || !std::isfinite(d[2][k])) {
        return false;
      }
    }
    SideMoments m;
    if (!AccumulateSide(intrinsics_, loss, value, points,
                        side == 0 ? observation_.left_weights : observation_.right_weights,
                        &lin->cost, &m)) {
      return false;
    }
    // J'J = dl' a dl and J'f = dl' b over the side's rows.
    double ad[3][4];
    for (int c = 0; c < 3; ++c) {
      for (int k = 0; k < 4; ++k) {
        ad[c][k] = m.a[c][0] * d[0][k] + m.a[c][1] * d[1][k] + m.a[c][2] * d[2][k];
      }
    }
    for (int k = 0; k < 4; ++k) {
      for (int j = k; j < 4; ++j) {
        normal[k][j] += d[0][k] * ad[0][j] + d[1][k] * ad[1][j] + d[2][k] * ad[2][j];
      }
      normal[k][4] += d[0][k] * m.b[0] + d[1][k] * m.b[1] + d[2][k] * m.b[2];
    }
  }
  for (int k = 0; k < 4; ++k) {
    lin->gradient[k] = normal[k][4];
    lin->column_sq[k] = normal[k][k];
  }
  bounded_lm::NormalToTriangular<4>(normal, lin->r);
  return std::isfinite(lin->cost);
}

}  // namespace corridor
