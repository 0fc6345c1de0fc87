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

// One wall on its baseboard's top: its ceiling side higher than the other's by h / (h - b), b
// within the options' heights (each side found with the ceiling search's minimum support). The
// foot of the band below its junction, passing the same band and reflection tests, moving it in
// by that ratio within ceiling_ratio (the other wall staying within same_ratio), is its junction.
// Taken, as TakeBothBaseboardFeet.
BaseboardFeet TakeOneBaseboardFoot(const WallCheckInputs& in, const BaseboardFeetOptions& options,
                                   CorridorGeometry* geometry, RecoverDepthResult* result);

// One wall on its baseboard's top, whatever the ceiling says (its sides too weak to find, or read
// off other lines: a window band's top): the foot of the band below its junction is taken when
// the other wall shows the band's top at the height b the foot gives (CorridorLineSupport over
// min_across_support) and the wall moved shows none at b above its line first taken (over
// max_above_support), the band passes the band and reflection tests and the other wall stays.
// Exactly one wall may pass. Taken, as TakeBothBaseboardFeet. Run after TakeOneBaseboardFoot.
BaseboardFeet TakeFootShownAcross(const WallCheckInputs& in, const BaseboardFeetOptions& options,
                                  CorridorGeometry* geometry, RecoverDepthResult* result);

}  // namespace corridor
