#pragma once

#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "corridor_depth/camera.h"
#include "corridor_depth/corridor_geometry.h"
#include "corridor_depth/status.h"
#include "perception/oriented_edges.h"
#include "corridor_depth/stage_options.h"
#include "corridor_depth/stage_results.h"

namespace corridor {

// Searches the ceiling height whose two ceiling/wall junctions, (-d_l, h - H_c, Z) and
// (d_r, h - H_c, Z), best follow the image's edges; then each edge pixel near the chosen lines
// gives H_c from its ray's intersection with its wall plane, and the median is the estimate.
// `bgr` is the raw image; the camera's distortion is honoured. Never fails on bad images:
// estimate->found is false with a reason. `edges`: null, or the frame's edges of `bgr` shared by
// its searches (ComputeImageEdges, or empty at first), used where they cover the rows searched
// and otherwise filled from the top down far enough (ComputeOrientedEdges).
Status DetectCeiling(const cv::Mat& bgr, const Camera& camera, const CorridorGeometry& geometry,
                     const CeilingDetectorOptions& options, CeilingEstimate* estimate,
                     ImageEdges* edges = nullptr);

// Fraction of the corridor line (x, y, Z) (a wall's junction with the floor at y = camera height,
// or with the ceiling) on edges of its orientation, its samples taken as the ceiling search takes
// them (options.samples, near_distance to far_distance, evenly in inverse distance) and judged as
// it judges its chosen lines: over the samples in view, at least min_counted_fraction counted.
// `edges` as for DetectCeiling, extended down to the line's rows. 0 when no sample is in view.
double CorridorLineSupport(const cv::Mat& bgr, const Camera& camera, const CorridorGeometry& g,
                           double x, double y, const CeilingDetectorOptions& options,
                           ImageEdges* edges = nullptr);

// CorridorLineSupport of the lines (x, y, Z) for each x of `xs`, their edges read once over all
// their rows: the same values, one per x.
std::vector<double> CorridorLinesSupport(const cv::Mat& bgr, const Camera& camera,
                                         const CorridorGeometry& g, const std::vector<double>& xs,
                                         double y, const CeilingDetectorOptions& options,
                                         ImageEdges* edges = nullptr);

// The best CorridorLineSupport of the floor junctions (x * r, camera height), r from 1 / spread to
// spread in steps of 0.01: how well a junction near x (give or take its uncertainty, the factor
// `spread`) follows edges. Only g's rotation and camera height are used.
double BestFloorLineSupportNear(const cv::Mat& bgr, const Camera& camera,
                                const CorridorGeometry& g, double x, double spread,
                                const CeilingDetectorOptions& options,
                                ImageEdges* edges = nullptr);

}  // namespace corridor
