#pragma once

#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "corridor_depth/camera.h"
#include "corridor_depth/corridor_geometry.h"
#include "corridor_depth/status.h"

namespace corridor {

// One photo's hand labels (junctions.csv, as tests/data/real-corridors/README.md describes it):
// two points on each visible floor/wall junction, in raw pixels of the file as stored.
struct JunctionLabel {
  std::string file;                        // The photo's file name, beside junctions.csv.
  int width = 0, height = 0;               // Its size, pixels.
  bool has_side[2] = {false, false};       // Left, right: labelled (not hidden).
  std::array<Eigen::Vector2d, 2> side[2];  // Left, right: near point, far point.
  std::string kind;                        // "corridor", or "other" (a view not along one corridor).
  std::string quality;                     // "sure", or "approx" (partly inferred).
  bool has_camera = false;                 // The intrinsics below are known.
  double fx = 0, fy = 0, cx = 0, cy = 0;
};

// Reads junctions.csv; InvalidArgument naming the file and line of a malformed row.
Status ReadJunctionLabels(const std::string& path, std::vector<JunctionLabel>* labels);

// The image line a*u + b*v + c = 0 (a^2 + b^2 = 1), in ideal pixels, of the floor/wall junction
// that `geometry` puts on `side` (0 left, 1 right): the 3D line (-d_l, h, s) or (d_r, h, s) of
// docs/geometry.md projected. A frame recovered level (RecoverDepthResult::roll) has its geometry
// in the level camera: `roll` turns the line back into the frame's own pixels. False when the
// geometry has no such wall or it is behind the camera.
bool ProjectedJunction(const CorridorGeometry& geometry, const Camera& camera, int side,
                       Eigen::Vector3d* line, double roll = 0);

// What a frame's reported junctions are worth against a label.
enum class LabelVerdict {
  kRight,       // Reported ok, every labelled side within 2% of the image height.
  kRough,       // Reported ok, in between.
  kOkButWrong,  // Reported ok, a labelled side off by more than 5% of the height.
  kRefused,     // No geometry reported.
};
const char* LabelVerdictName(LabelVerdict verdict);

struct LabelScore {
  LabelVerdict verdict = LabelVerdict::kRefused;
  // Per side: the largest distance over the labelled segment to the projected junction, as a
  // fraction of the image height; negative when the side is not labelled or was not scored.
  double side_error[2] = {-1, -1};
};

// Scores a reported geometry (ok = it was reported as the frame's result) against the label. The
// distance along a segment to a line is largest at one of its ends, so the ends are measured.
// A labelled side whose junction the geometry cannot project counts as off by the full height.
// `roll`: the frame's RecoverDepthResult::roll (ProjectedJunction).
LabelScore ScoreAgainstLabel(const JunctionLabel& label, bool ok, const CorridorGeometry& geometry,
                             const Camera& camera, double roll = 0);

}  // namespace corridor
