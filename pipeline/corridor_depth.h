#pragma once

// The one header research code includes:
//   #include "pipeline/corridor_depth.h"
//   corridor::RecoverDepthResult result;
//   corridor::RecoverDepth(image, camera, corridor::RecoverDepthOptions(), &result);

#include "core/camera.h"                   // IWYU pragma: export
#include "core/corridor_geometry.h"        // IWYU pragma: export
#include "core/status.h"                   // IWYU pragma: export
#include "depth/rasterizer.h"              // IWYU pragma: export
#include "estimation/solver.h"             // IWYU pragma: export
#include "io/camera_yaml.h"                // IWYU pragma: export
#include "io/image_io.h"                   // IWYU pragma: export
#include "perception/junction_detector.h"  // IWYU pragma: export
#include "pipeline/recover_depth.h"        // IWYU pragma: export
#include "pipeline/sequence_prior.h"       // IWYU pragma: export
#include "pipeline/visualization.h"        // IWYU pragma: export
