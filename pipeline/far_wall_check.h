#pragma once

#include <opencv2/core.hpp>

#include "corridor_depth/camera.h"
#include "corridor_depth/corridor_geometry.h"
#include "corridor_depth/stage_options.h"
#include "corridor_depth/stage_results.h"
#include "perception/oriented_edges.h"
#include "pipeline/inner_line_check.h"

namespace corridor {

// A wall put far too far (a line seen through a glass wall, or a recess's or a side room's floor
// line, taken for its junction) puts its own ceiling junction higher than any ceiling: the
// ceiling search (`found`, its sides searched alone up to ceiling.max_height) sees none on that
// side, while the other side's is plainly seen (strong_support on its samples in view). Sought
// from max_height up to options.far_max_height, that side's ceiling junction shows; the wall then
// moves in by the ratio of the two sides' heights above the camera, where its floor junction must
// follow edges (min_far_target_support). Updates *geometry when it moves; `bgr`, `camera` and
// `edges` as for CheckInnerLine.
InnerLineCheck CheckFarWall(const cv::Mat& bgr, const Camera& camera,
                            const CeilingDetectorOptions& ceiling,
                            const InnerLineCheckOptions& options, const CeilingEstimate& found,
                            CorridorGeometry* geometry, ImageEdges* edges = nullptr);

}  // namespace corridor
