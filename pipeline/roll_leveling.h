#pragma once

#include "corridor_depth/camera.h"
#include "corridor_depth/corridor_geometry.h"
#include "corridor_depth/recover_depth.h"

namespace corridor {

// After an ok frame (`result`, recovered as seen): estimates the camera's roll (EstimateRoll, on
// the frame's handover image with the frame's own yaw and pitch) and, when its evidence is
// clear, recovers the frame turned level by `level` (a recoverer without level_roll) and takes
// that: its geometry, ceiling, end wall, confidence and depth (turned back to the frame's
// pixels, NaN where the turned frame had none), with result->roll set and a note. The junction
// lines stay the frame's own (its pixels). When the level frame is not ok, the frame keeps its
// own answer, with a note; so it does when the level frame's confidence is lower than its own.
// The choice is made on the layouts (DepthRecoverer::ReconstructLayout), before any depth; a level
// frame taken is finished by `level` (its solver, its depth) and true returned; false when the
// frame keeps its own layout, still to be finished.
bool LevelRoll(const DepthRecoverer& level, const Camera& camera,
               const CorridorGeometry* previous, RecoverDepthResult* result);

}  // namespace corridor
