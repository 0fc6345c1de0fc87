#pragma once

#include <opencv2/core.hpp>

#include "corridor_depth/camera.h"
#include "corridor_depth/corridor_geometry.h"
#include "corridor_depth/stage_options.h"
#include "corridor_depth/stage_results.h"
#include "perception/oriented_edges.h"

namespace corridor {

// The ceiling's evidence against the geometry's walls (CeilingSplitOptions): |log| of the ratio of
// the two ceiling sides' heights above the camera when each side's own junction is plainly seen,
// the height both sides best share leaves one of them off the edges, and moving either wall to
// agree with the other side's ceiling (the far one in, or the near one out, by that ratio) puts its
// floor junction on a line that follows edges. -1 otherwise: the sides agree, one is too faint to
// tell, or no line explains the disagreement (a camera's roll, a window band read as the ceiling).
// `ceiling` is the ceiling search for `geometry` (DetectCeiling); `bgr` and `camera` those it
// searched, `edges` its shared edges (may be null).
double CeilingSplit(const cv::Mat& bgr, const Camera& camera, const CorridorGeometry& geometry,
                    const CeilingEstimate& ceiling, const CeilingDetectorOptions& ceiling_options,
                    const CeilingSplitOptions& options, ImageEdges* edges = nullptr);

}  // namespace corridor
