#include "estimation/junction_residuals.h"

#include <cmath>
#include <vector>

#include "estimation/side_moments.h"

namespace corridor {

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
    if (!AccumulateSideMoments(
            intrinsics_, loss, value, points,
            side == 0 ? observation_.left_weights : observation_.right_weights, &lin->cost, &m)) {
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
