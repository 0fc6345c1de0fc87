#include "perception/single_junction.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <Eigen/Geometry>

namespace corridor {

int OutermostFloorEdge(const std::vector<JunctionCandidate>& side, bool is_left, int height) {
  double best_boundary = 0;
  for (const auto& c : side) best_boundary = std::max(best_boundary, c.boundary);
  const auto bottom_u = [&](const MergedLine& l) {  // u where the line meets the bottom row.
    return std::abs(l.line.x()) > 1e-9 ? -(l.line.y() * height + l.line.z()) / l.line.x() : 0.0;
  };
  size_t best = 0;
  bool found = false;
  for (size_t i = 0; i < side.size(); ++i) {
    if (side[i].boundary < std::max(0.3, 0.5 * best_boundary)) continue;
    const double u = bottom_u(side[i].line), best_u = bottom_u(side[best].line);
    if (!found || (is_left ? u < best_u : u > best_u)) best = i;
    found = true;
  }
  return found ? static_cast<int>(best) : -1;
}

bool VoteSingleVanishingPoint(const JunctionLine& single, const MergedLine& chosen,
                              const std::vector<MergedLine>& lines, double shortest, int height,
                              Eigen::Vector2d* vp, int* votes) {
  // Crossings of the other lines with this one, above its support's far end.
  const Eigen::Vector3d& l = single.line;
  const Eigen::Vector2d direction(l.y(), -l.x());
  const Eigen::Vector2d origin = -l.z() * l.head<2>();
  const double far_t = (single.far_end - origin).dot(direction);
  const double near_t = (single.near_end - origin).dot(direction);
  const double up = far_t < near_t ? -1.0 : 1.0;     // Sign of t toward the far end.
  std::vector<std::pair<double, double>> crossings;  // (t, weight)
  double total = 0;
  for (const MergedLine& other : lines) {
    if (&other == &chosen || other.length < shortest) continue;
    const Eigen::Vector3d x = l.cross(other.line);
    if (std::abs(x.z()) < 1e-9) continue;
    const Eigen::Vector2d p = x.head<2>() / x.z();
    const double t = (p - origin).dot(direction);
    if ((t - far_t) * up < -2.0) continue;  // Crosses on the support: not a vanishing point.
    if (std::abs(l.head<2>().dot(other.line.head<2>())) > std::cos(5.0 * M_PI / 180)) continue;
    crossings.emplace_back(t, other.length);
    total += other.length;
  }
  if (crossings.size() < 2) return false;
  std::sort(crossings.begin(), crossings.end());
  double running = 0, median = crossings.front().first;
  for (const auto& [t, w] : crossings) {
    running += w;
    median = t;
    if (running >= 0.5 * total) break;
  }
  // Most votes must agree (within 3% of the image height along the line).
  int agree = 0;
  for (const auto& [t, w] : crossings) agree += std::abs(t - median) < 0.03 * height;
  if (agree < 2 || agree * 2 < static_cast<int>(crossings.size())) return false;
  *vp = origin + median * direction;
  *votes = agree;
  return true;
}

}  // namespace corridor
