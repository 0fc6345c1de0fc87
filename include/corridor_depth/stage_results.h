#pragma once

// What the pipeline's stages report beside the geometry (RecoverDepthResult).

#include <string>

namespace corridor {

struct CeilingEstimate {
  bool found = false;        // True when at least one ceiling/wall junction was seen.
  double height = 0;         // H_c, m above the floor (valid when found).
  double left_support = 0;   // Fraction of the left junction's visible samples on edges (at least min_counted_fraction of the samples counted).
  double right_support = 0;  // Same for the right one.
  int points = 0;            // Edge pixels whose rays gave the robust (median) estimate.
  // Each side searched alone: the height whose junction on that wall best follows the edges, and
  // its support. A wrong wall distance scales its side's height, so the two then disagree.
  double side_height[2] = {0, 0};           // Left, right: H_c, m (0 when the side has no line).
  double side_support[2] = {0, 0};          // Left, right: the support of that line (of at least half the samples, as the search counts).
  double side_visible_support[2] = {0, 0};  // Left, right: the same line's support on its samples in view (at least min_counted_fraction counted, as the chosen lines are judged).
  std::string reason;                       // Why nothing was found.
};

struct EndWallEstimate {
  bool found = false;   // True when an end wall was seen.
  double distance = 0;  // Its Z_W, m along the corridor from the camera (valid when found).
  double support = 0;   // The second-best third's fraction of the floor/end-wall line on edges.
  double beyond = 0;    // The cleaner junction's fraction on edges just beyond the wall.
  double corner = 0;    // The corners' largest fraction on edges.
  double before = 0;    // The junctions' largest fraction on edges just before the wall.
  int points = 0;       // Edge pixels whose rays gave the robust (median) distance.
  std::string reason;   // Why nothing was found.
};

// Door frames, wall corners, lockers' and baseboards' ends are vertical and stop at the floor:
// where such an edge meets a true floor/wall junction from above, the floor lies below it. A
// handrail, chair rail, wainscot top, window sill or bench edge taken for the junction is crossed
// by them instead: the wall, and its vertical edges, go on below the line. This counts, along a
// junction, the places where a vertical edge runs down to it from above, and those where one also
// goes on below it.
struct VerticalCrossings {
  int reaching = 0;  // Vertical edges that run down to the junction from above.
  int crossing = 0;  // Of those, the ones that go on below it.
  int samples = 0;   // Points of the junction that were examined.
  // crossing / reaching; 0 when fewer than `min_reaching` edges reach the junction.
  double CrossingFraction(int min_reaching = 2) const {
    return reaching >= min_reaching ? static_cast<double>(crossing) / reaching : 0.0;
  }
};

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
  // |log| of the ratio of the two ceiling sides' heights above the camera when each side is plainly
  // seen, no one height explains both, and a wall moved to agree with the other side's ceiling
  // would stand on a line that follows edges (CeilingSplitOptions); -1 otherwise.
  double ceiling_split = -1;
  // Per side: the fraction of the junction line, up to the depth the other junction's support
  // reaches, where the floor goes on across it with no edge on the line (an object's front foot
  // taken for the wall's: FloorBeyond, pipeline/floor_beyond_junction.h); -1 when not measured.
  double floor_across[2] = {-1, -1};
};

}  // namespace corridor
