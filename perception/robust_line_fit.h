#pragma once

#include <vector>

#include <Eigen/Core>

namespace corridor {

// The line (a, b, c), a^2 + b^2 = 1, b >= 0, with the least sum of distances to the points, as
// cv::fitLine(DIST_HUBER) picks it among its iterates: iteratively reweighted total least squares
// from the unweighted fit, first with Huber weights min(1, 1.345 / d), then with L1 weights
// 1 / max(d, 0.05), keeping the iterate with the least sum (at most 60 iterations). One
// deterministic start, where cv::fitLine tries 20 random ones. False (and *line untouched) for
// fewer than 8 points or a degenerate fit. Each iteration is one pass over the points, four at a
// time (AVX2 where the CPU has it): the distances, their sum and the next line's weighted sums.
bool FitLineLeastDistance(const std::vector<Eigen::Vector2d>& points, Eigen::Vector3d* line);

}  // namespace corridor
