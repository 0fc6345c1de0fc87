#pragma once

#include "corridor_depth/camera.h"
#include "corridor_depth/corridor_geometry.h"
#include "corridor_depth/status.h"
#include "corridor_depth/corridor_observation.h"
#include "corridor_depth/junction_lines.h"
#include "corridor_depth/recover_depth.h"

namespace corridor {

// Is the estimate a corridor? kImplausibleGeometry with the reason otherwise.
Status CheckPlausible(const CorridorGeometry& geometry, const RecoverDepthOptions& options);

// Does the estimate explain the junctions it was fitted to? kImplausibleGeometry when the RMS
// pixel distance of the observation's points to the junction lines the geometry predicts exceeds
// options.max_line_error times the camera's image diagonal: the lines fit no corridor (parallel,
// meeting below the points) or the solver stopped at the edge of its search range.
Status CheckLineFit(const CorridorGeometry& geometry, const CorridorObservation& observation,
                    const Camera& camera, const RecoverDepthOptions& options);

}  // namespace corridor
