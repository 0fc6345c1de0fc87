#pragma once

#include <vector>

#include <Eigen/Core>

namespace corridor {

// Marks the points that lie on the points' dominant line: a total-least-squares fit, refitted up
// to 3 times without the points farther than max(3 sigma_MAD, 1 px) from it. All points are
// inliers when they are fewer than 3 or already collinear within 1 px.
std::vector<char> LineInlierMask(const std::vector<Eigen::Vector2d>& points);
// The same into *keep, which keeps its memory.
void LineInlierMask(const std::vector<Eigen::Vector2d>& points, std::vector<char>* keep);

}  // namespace corridor
