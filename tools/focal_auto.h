#pragma once

#include <string>

#include "corridor_depth/status.h"
#include "tools/input_source.h"

namespace corridor {

// --focal=auto for one scene: the focal length from two orthogonal vanishing points
// (perception/focal_estimator.h) on up to five frames spread over the scene (a bag or video: its
// first frame), the median of those that had them; else the focal of `fallback_hfov_deg`. *how
// says which, for the tool to print and record.
Status EstimateSceneFocal(const InputScene& scene, double fallback_hfov_deg, double* focal_px,
                          std::string* how);

}  // namespace corridor
