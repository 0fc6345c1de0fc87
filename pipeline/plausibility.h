#pragma once

#include "corridor_depth/camera.h"
#include "corridor_depth/corridor_geometry.h"
#include "corridor_depth/status.h"
#include "corridor_depth/corridor_observation.h"
#include "corridor_depth/junction_lines.h"
#include "corridor_depth/recover_depth.h"

namespace corridor {

// Is the estimate a corridor? kImplausibleGeometry with the reason otherwise: CheckPlausibleShape
// and CheckCorridorWidth.
Status CheckPlausible(const CorridorGeometry& geometry, const RecoverDepthOptions& options);

// Finite, yaw and pitch within options' bounds, the camera between the walls: what a layout tried
// as a hypothesis (the solver's first answer, a wall the ceiling's checks would move) must be.
Status CheckPlausibleShape(const CorridorGeometry& geometry, const RecoverDepthOptions& options);

// The width within [options.min_width, options.max_width]: asked of the layout a frame reports,
// after the checks that may move its walls (a rail taken for a junction on both walls gives a
// width that a baseboard or ceiling check may bring back).
Status CheckCorridorWidth(const CorridorGeometry& geometry, const RecoverDepthOptions& options);

// Does the estimate explain the junctions it was fitted to? kImplausibleGeometry when the RMS
// pixel distance of the observation's points to the junction lines the geometry predicts exceeds
// options.max_line_error times the camera's image diagonal: the lines fit no corridor (parallel,
// meeting below the points) or the solver stopped at the edge of its search range.
Status CheckLineFit(const CorridorGeometry& geometry, const CorridorObservation& observation,
                    const Camera& camera, const RecoverDepthOptions& options);

}  // namespace corridor
