#pragma once

#include <random>

#include "corridor_depth/corridor_geometry.h"
#include "corridor_depth/corridor_observation.h"

namespace corridor {

// Noisy junction points for the solver comparison, projected with Eigen's rotations from a
// random corridor pose (independent of the solvers' own frame code).
struct JunctionSweepCase {
  double noise_px = 0;          // Gaussian pixel noise on both coordinates.
  double outlier_fraction = 0;  // Points moved by 10-50 px in a random direction.
  int points_per_side = 30;     // Points sampled along each junction, near to far.
};

// A random plausible corridor: yaw within +-0.25 rad, pitch in [-0.05, 0.15], width 1.5-4 m,
// offset within +-30% of the width, camera height 0.3-1.5 m.
CorridorGeometry RandomCorridor(std::mt19937* rng);

// The observation of `truth` by a 640x480 camera (fx = fy = 500): points on both junctions
// between 1.5 and 20 m, kept when inside the image, then noise and outliers.
CorridorObservation ObserveJunctions(const CorridorGeometry& truth, const JunctionSweepCase& c,
                                     std::mt19937* rng);

}  // namespace corridor
