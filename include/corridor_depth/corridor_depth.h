#pragma once

// The one header research code includes:
//   #include <corridor_depth/corridor_depth.h>
//   corridor::RecoverDepthResult result;
//   corridor::RecoverDepth(image, camera, corridor::RecoverDepthOptions(), &result);
// The solvers' cost functors (symmetry_residual.h, width_residual.h), the metrics
// (depth_metrics.h), the evaluation engine (evaluation.h) and the file formats (truth_yaml.h,
// dataset.h, ply_io.h) have headers of their own beside it.

#include "corridor_depth/camera.h"             // IWYU pragma: export
#include "corridor_depth/camera_yaml.h"        // IWYU pragma: export
#include "corridor_depth/corridor_geometry.h"  // IWYU pragma: export
#include "corridor_depth/depth_sequence.h"     // IWYU pragma: export
#include "corridor_depth/image_io.h"           // IWYU pragma: export
#include "corridor_depth/rasterizer.h"         // IWYU pragma: export
#include "corridor_depth/recover_depth.h"      // IWYU pragma: export
#include "corridor_depth/solver.h"             // IWYU pragma: export
#include "corridor_depth/status.h"             // IWYU pragma: export
#include "corridor_depth/visualization.h"      // IWYU pragma: export
