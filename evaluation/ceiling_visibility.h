#pragma once

// Whether a frame shows its ceiling/wall junctions: the evaluation's own test of where the
// ceiling-height criterion applies. It projects the true junctions (docs/geometry.md, section 6:
// (-d_l, h - H_c, Z) and (d_r, h - H_c, Z) in the corridor frame) through the true geometry, and
// measures how much of them lands inside the image. It uses nothing of the ceiling search.

#include "corridor_depth/camera.h"
#include "corridor_depth/corridor_geometry.h"

namespace corridor {

// What counts as a visible ceiling junction.
struct CeilingVisibilityOptions {
  double max_depth = 40.0;           // Farthest junction point considered, m along the corridor (or the end wall, if nearer).
  double min_length_fraction = 0.1;  // Visible when one junction's image length inside the frame reaches this fraction of the image's smaller side.
};

// Length in pixels of the part of one true ceiling/wall junction (side -1 left, +1 right) that
// projects inside the image, for corridor depths Z in (0, max_depth]. 0 when the geometry has no
// ceiling above the camera, or is not finite.
double VisibleCeilingJunctionLength(const CorridorGeometry& truth, const Camera& camera, int side,
                                    const CeilingVisibilityOptions& options = {});

// True when either junction's visible length reaches options.min_length_fraction of the image's
// smaller side.
bool CeilingJunctionVisible(const CorridorGeometry& truth, const Camera& camera,
                            const CeilingVisibilityOptions& options = {});

}  // namespace corridor
