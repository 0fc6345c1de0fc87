#pragma once

#include <vector>

#include <Eigen/Core>

#include "corridor_depth/corridor_geometry.h"
#include "corridor_depth/status.h"
#include "corridor_depth/corridor_observation.h"

namespace corridor {

// Total-least-squares line a u + b v + c = 0 (a^2 + b^2 = 1) through >= 2 points.
// Returns false for fewer than 2 distinct points.
bool FitImageLine(const std::vector<Eigen::Vector2d>& points, Eigen::Vector3d* line);
// The same, each point's squared distance weighted (`weights` empty = all 1, else one per point).
bool FitImageLine(const std::vector<Eigen::Vector2d>& points, const std::vector<double>& weights,
                  Eigen::Vector3d* line);

// The vanishing-point solution of docs/geometry.md, section 4, from the two junction lines fitted
// to the observation's points (each side's gross outliers trimmed first, see LineInlierMask; the
// lines are weighted fits and the lateral positions weighted medians when the points have weights). Exact for noise-free lines. Fails (kImplausibleGeometry) when the
// lines are parallel in the image (vanishing point at infinity), when the vanishing point lies
// behind the camera, or when the points do not back-project onto the floor.
Status SolveClosedForm(const CorridorObservation& observation, CorridorGeometry* geometry);

}  // namespace corridor
