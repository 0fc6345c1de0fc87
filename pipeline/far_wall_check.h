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
// line, taken for its junction) puts its own ceiling junction higher than any ceiling, where the
// ceiling search (`found`, each side searched alone up to ceiling.max_height) does not look.
// With the other side's ceiling junction plainly seen (min_far_ceiling_support of its samples in
// view), the far side's is sought at that height for the wall moved in by r, r from where the
// search's heights end up to options.far_max_height's; plainly seen too, and better than the far
// side's own in the search, the wall moves in by that r, where its floor junction must follow
// edges (min_far_target_support). Updates *geometry when it moves; `bgr`, `camera` and `edges`
// as for CheckInnerLine.
InnerLineCheck CheckFarWall(const cv::Mat& bgr, const Camera& camera,
                            const CeilingDetectorOptions& ceiling,
                            const InnerLineCheckOptions& options, const CeilingEstimate& found,
                            CorridorGeometry* geometry, ImageEdges* edges = nullptr);

}  // namespace corridor
