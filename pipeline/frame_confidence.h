#pragma once

#include <string>

#include "core/corridor_geometry.h"
#include "perception/junction_lines.h"
#include "perception/vertical_crossings.h"
#include "perception/working_image.h"

namespace corridor {

// What a frame's layout rests on, each part measured on the frame's own image.
struct FrameEvidence {
  // Per side (left, right): the detector's confidence in the junction line, in [0, 1] (its
  // boundary score times its support length, JunctionLine::confidence); -1 when the side has no
  // line (one junction and a known width).
  double junction[2] = {-1, -1};
  // |log| of the ratio of the two ceiling sides' heights above the camera, each side searched
  // alone: a wrong wall distance scales its side's height. -1 when they cannot be compared (no
  // ceiling in view, or a side too weak).
  double ceiling_disagreement = -1;
  // Per side: vertical edges (door frames, corners) reaching the junction from above, and those
  // that go on below it (vertical_crossings.h).
  VerticalCrossings crossings[2];
  // The geometry is not the two junctions' alone: one junction and a known width, a held width, a
  // lower parallel line taken, or walls scaled to a held ceiling.
  bool corrected = false;
  // The side whose wall the inner-line check moved out to where its ceiling junction agrees with
  // the other side's (0 left, 1 right; -1 none): the geometry then rests on the ceiling's evidence.
  int moved_side = -1;
};

// The frame's confidence in [0, 1]: the product of one factor per kind of evidence, each 1 when
// that evidence is good or absent, lower when it speaks against the layout (docs/method.md,
// "Frame confidence"). `why` (may be null) receives the weakest factor's reason, for a refusal's
// message.
double FrameConfidence(const FrameEvidence& evidence, std::string* why = nullptr);

// The evidence for a frame's geometry: the junction lines' own confidence (the one line, when one
// junction is hidden), the vertical edges crossing them, counted on `search` (the frame at the
// search resolution; none when it is empty), and what the reconstruction did (the ceiling sides'
// disagreement, -1 when not compared; a correction; the wall the inner-line check moved).
FrameEvidence GatherFrameEvidence(const JunctionPair& junctions, const WorkingImage& search,
                                  const CorridorGeometry& geometry, double ceiling_disagreement,
                                  bool corrected, int moved_side,
                                  const VerticalCrossingOptions& options);

}  // namespace corridor
