#pragma once

#include <opencv2/core.hpp>

#include "corridor_depth/camera.h"
#include "corridor_depth/corridor_observation.h"
#include "corridor_depth/junction_lines.h"
#include "corridor_depth/recover_depth.h"

namespace corridor {

// True when options.solver_evidence asks for the measured edge points ("edges").
bool SolverSeesEdges(const RecoverDepthOptions& options);

// When the solvers are to see edge points: each junction's (left, right and the lower
// alternatives) measured on `bgr` (the frame, raw pixels) into its edge_points and edge_weights
// (MeasureJunctionEdgePoints). Nothing otherwise.
void MeasureSolverEvidence(const cv::Mat& bgr, const RecoverDepthOptions& options,
                           JunctionPair* junctions);

// The solvers' input from detected junctions, with the camera's intrinsics and height, in ideal
// (undistorted) pixels: with solver_evidence "edges", each side's measured edge points and their
// weights where it has at least points_per_line of them; else (and with "lines")
// options.points_per_line points sampled along its fitted line, of weight 1.
CorridorObservation ObservationFromJunctions(const JunctionPair& junctions, const Camera& camera,
                                             const RecoverDepthOptions& options);
// The same into *observation, whose vectors keep their memory.
void ObservationFromJunctions(const JunctionPair& junctions, const Camera& camera,
                              const RecoverDepthOptions& options,
                              CorridorObservation* observation);

}  // namespace corridor
