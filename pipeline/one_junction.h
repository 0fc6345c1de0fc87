#pragma once

#include <string>

#include "corridor_depth/camera.h"
#include "corridor_depth/corridor_geometry.h"
#include "corridor_depth/status.h"
#include "corridor_depth/junction_lines.h"

namespace corridor {

// The geometry from the one visible floor/wall junction (the other one hidden), when the
// corridor's width is known: a width prior given as an option, or the previous frame's width in a
// sequence. Yaw and pitch come from where other lines meet the junction (its vanishing point);
// without one, from the previous frame's pitch (`prior`, may be null), the yaw then from where the
// junction crosses that pitch's horizon. The junction's floor points give the distance to its wall
// (docs/geometry.md s4: P_W = R^T (h / n.r) r), the width the other wall. kNoCorridorFound with the
// reason when this is not possible; *how says what was used.
Status GeometryFromOneJunction(const JunctionPair& pair, const Camera& camera, double width,
                               const CorridorGeometry* prior, CorridorGeometry* geometry,
                               std::string* how);

}  // namespace corridor
