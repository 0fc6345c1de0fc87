#pragma once

#include <string>

#include "corridor_depth/corridor_geometry.h"
#include "corridor_depth/junction_lines.h"
#include "perception/vertical_crossings.h"
#include "perception/working_image.h"
#include "corridor_depth/stage_results.h"

namespace corridor {

// The frame's confidence in [0, 1]: the product of one factor per kind of evidence, each 1 when
// that evidence is good or absent, lower when it speaks against the layout (docs/method.md,
// "Frame confidence"). `why` (may be null) receives the weakest factor's reason, for a refusal's
// message.
double FrameConfidence(const FrameEvidence& evidence, std::string* why = nullptr);

// True when the floor goes on across side s's junction (0 left, 1 right) on enough of its length
// to weigh against the layout: the line may be an object's front foot, not the wall's.
bool FloorGoesOnAcross(const FrameEvidence& evidence, int s);

// True when side s's junction line has the edge support of a plain junction: its confidence is
// high enough that its support does not weigh against the layout.
bool JunctionFullySupported(const FrameEvidence& evidence, int s);

// The evidence for a frame's geometry: the junction lines' own confidence (the one line, when one
// junction is hidden), the vertical edges crossing them, counted on `search` (the frame at the
// search resolution; none when it is empty), and what the reconstruction did (the ceiling sides'
// disagreement, -1 when not compared; a correction; the wall the inner-line check moved), and the
// ceiling's split (CeilingSplit, -1 none).
FrameEvidence GatherFrameEvidence(const JunctionPair& junctions, const WorkingImage& search,
                                  const CorridorGeometry& geometry, double ceiling_disagreement,
                                  bool corrected, int moved_side,
                                  const VerticalCrossingOptions& options,
                                  double ceiling_split = -1);

}  // namespace corridor
