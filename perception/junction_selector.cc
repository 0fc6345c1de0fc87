#include "perception/junction_selector.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

namespace corridor {
namespace {

// Fraction (by length) of the other lines that point at the vanishing point: the corridor's
// parallel edges (grout, door tops, skirting) all meet there.
double VanishingSupport(const Eigen::Vector2d& vp, const std::vector<MergedLine>& lines,
                        double diagonal) {
  double agree = 0, total = 0;
  for (const auto& l : lines) {
    if (l.inclination_deg < 2 || l.inclination_deg > 88) continue;  // Horizontal or vertical.
    total += l.length;
    // Angle between the line and the direction from its middle to the vanishing point.
    const Eigen::Vector2d mid = 0.5 * (l.start + l.end);
    const Eigen::Vector2d to_vp = vp - mid;
    if (to_vp.norm() < 1e-6) continue;
    const Eigen::Vector2d direction = (l.end - l.start).normalized();
    const double sin_angle = std::abs(direction.x() * to_vp.y() - direction.y() * to_vp.x()) /
                             to_vp.norm();
    // Tolerance: 2 px at the vanishing point's distance, at least 1 degree.
    const double tolerance = std::max(std::sin(M_PI / 180.0), 2.0 / std::max(to_vp.norm(), 1.0));
    if (sin_angle < tolerance) agree += l.length;
  }
  (void)diagonal;
  return total > 0 ? agree / total : 0.0;
}

}  // namespace

SelectedPair SelectJunctionPair(const std::vector<JunctionCandidate>& left,
                                const std::vector<JunctionCandidate>& right,
                                const std::vector<MergedLine>& all_lines,
                                const Eigen::Vector2d& size) {
  SelectedPair best;
  const double width = size.x(), height = size.y(), diagonal = size.norm();
  for (size_t i = 0; i < left.size(); ++i) {
    for (size_t j = 0; j < right.size(); ++j) {
      const MergedLine& l = left[i].line;
      const MergedLine& r = right[j].line;
      const Eigen::Vector3d x = l.line.cross(r.line);
      if (std::abs(x.z()) < 1e-12) continue;
      const Eigen::Vector2d vp = x.head<2>() / x.z();
      // The vanishing point lies above both supports, with the left line to its left.
      const double top_left = std::min(l.start.y(), l.end.y());
      const double top_right = std::min(r.start.y(), r.end.y());
      if (vp.y() > std::min(top_left, top_right) + 2.0) continue;
      if (l.start.x() > vp.x() + 2.0 || r.end.x() < vp.x() - 2.0) continue;
      if (vp.x() < -width || vp.x() > 2 * width || vp.y() < -1.5 * height) continue;
      const double length_term = std::min(1.0, l.covered / (0.5 * height)) +
                                 std::min(1.0, r.covered / (0.5 * height));
      const double boundary_term = left[i].boundary + right[j].boundary;
      const double vp_term = VanishingSupport(vp, all_lines, diagonal);
      const double score = length_term + 2.0 * boundary_term + vp_term;
      if (best.left < 0 || score > best.score) {
        best.left = static_cast<int>(i);
        best.right = static_cast<int>(j);
        best.vanishing_point = vp;
        best.score = score;
      }
    }
  }
  return best;
}

}  // namespace corridor
