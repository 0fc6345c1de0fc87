#include "tools/compare/synthetic_junctions.h"

#include <cmath>

#include <Eigen/Geometry>

namespace corridor {

CorridorGeometry RandomCorridor(std::mt19937* rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const auto in = [&](double lo, double hi) { return lo + (hi - lo) * unit(*rng); };
  CorridorGeometry g;
  g.yaw = in(-0.25, 0.25);
  g.pitch = in(-0.05, 0.15);
  g.width = in(1.5, 4.0);
  g.offset = in(-0.3, 0.3) * g.width;
  g.camera_height = in(0.3, 1.5);
  return g;
}

CorridorObservation ObserveJunctions(const CorridorGeometry& truth, const JunctionSweepCase& c,
                                     std::mt19937* rng) {
  CorridorObservation obs;
  obs.fx = obs.fy = 500;
  obs.cx = 319.5;
  obs.cy = 239.5;
  obs.camera_height = truth.camera_height;
  const Eigen::Matrix3d r = (Eigen::AngleAxisd(truth.pitch, Eigen::Vector3d::UnitX()) *
                             Eigen::AngleAxisd(truth.yaw, Eigen::Vector3d::UnitY()))
                                .toRotationMatrix();
  std::normal_distribution<double> noise(0.0, c.noise_px > 0 ? c.noise_px : 1.0);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double walls[2] = {-(truth.width / 2 + truth.offset), truth.width / 2 - truth.offset};
  for (int side = 0; side < 2; ++side) {
    auto& points = side == 0 ? obs.left : obs.right;
    for (int i = 0; i < c.points_per_side; ++i) {
      // Uniform in inverse depth, like evenly spaced image rows.
      const double z = 1.0 / (1.0 / 1.5 + (1.0 / 20.0 - 1.0 / 1.5) * i / (c.points_per_side - 1));
      const Eigen::Vector3d pc = r * Eigen::Vector3d(walls[side], truth.camera_height, z);
      if (pc.z() <= 0.1) continue;
      Eigen::Vector2d p(obs.fx * pc.x() / pc.z() + obs.cx, obs.fy * pc.y() / pc.z() + obs.cy);
      if (p.x() < 0 || p.x() > 639 || p.y() < 0 || p.y() > 479) continue;
      if (c.noise_px > 0) p += Eigen::Vector2d(noise(*rng), noise(*rng));
      if (unit(*rng) < c.outlier_fraction) {
        const double angle = 2 * M_PI * unit(*rng), length = 10 + 40 * unit(*rng);
        p += length * Eigen::Vector2d(std::cos(angle), std::sin(angle));
      }
      points.push_back(p);
    }
  }
  return obs;
}

}  // namespace corridor
