#pragma once

#include "corridor_depth/stage_options.h"
#include "pipeline/wall_checks.h"

namespace corridor {

// What the baseboard-feet check (BaseboardFeetOptions) saw: each wall's ratio, its distance over
// its distance with its foot (0 when not measured), and whether the feet were taken.
struct BaseboardFeet {
  double ratio[2] = {0, 0};
  bool taken = false;
};

// The check on the frame's two junctions and their geometry, when the two ceiling sides agree
// (or cannot be compared). Taken, *geometry and result's junctions and solver summary become the
// feet's (the caller searches the ceiling again), with a note that says why.
BaseboardFeet TakeBothBaseboardFeet(const WallCheckInputs& in, const BaseboardFeetOptions& options,
                                    CorridorGeometry* geometry, RecoverDepthResult* result);

}  // namespace corridor
