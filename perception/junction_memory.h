#pragma once

// The junction search's result memory, per thread: the vectors of a result that is done with
// (RecycleJunctionMemory) serve the thread's next search instead of new ones.

#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "corridor_depth/junction_lines.h"

namespace corridor {

// Moves the memory of *junctions' lines' support and edge points and of its segments to the
// thread's spares (as many as one search fills), leaving those vectors empty.
void RecycleJunctionMemory(JunctionPair* junctions);

// An empty vector with a spare's memory when the thread has one; else a new one.
std::vector<Eigen::Vector2d> SpareSupport();
std::vector<Eigen::Vector2d> SpareEdgePoints();
std::vector<double> SpareEdgeWeights();
std::vector<cv::Vec4f> SpareSegments();

}  // namespace corridor
