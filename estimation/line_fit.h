#pragma once

#include "corridor_depth/corridor_geometry.h"
#include "corridor_depth/corridor_observation.h"

namespace corridor {

// How well a geometry explains the junction points it was fitted to: the RMS perpendicular pixel
// distance of the observation's points to the two junction lines the geometry projects
// (JunctionLineResidual), weighted by the points' weights. False when a line is undefined for the geometry or a distance is not
// finite; *rms is then meaningless.
bool JunctionLineRms(const CorridorGeometry& geometry, const CorridorObservation& observation,
                     double* rms);

}  // namespace corridor
