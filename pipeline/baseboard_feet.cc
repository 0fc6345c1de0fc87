#include "pipeline/baseboard_feet.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <Eigen/Geometry>

#include "perception/appearance.h"
#include "perception/ceiling_detector.h"
#include "perception/lower_edge.h"
#include "pipeline/ceiling_agreement.h"
#include "pipeline/plausibility.h"
#include "pipeline/solver_evidence.h"

namespace corridor {

bool BaseboardFeetOptions::Check(std::string* why) const {
  std::string reason;
  if (!(same_ratio >= 0 && same_ratio < 1)) {
    reason = "same_ratio must be in [0, 1) (0 = off)";
  } else if (!(min_height > 0 && max_height > min_height && std::isfinite(max_height))) {
    reason = "min_height must be > 0 m and max_height above it";
  } else if (!(min_band_contrast >= 0 && std::isfinite(min_band_contrast))) {
    reason = "min_band_contrast must be >= 0";
  } else if (!(max_band_fade > 0 && std::isfinite(max_band_fade))) {
    reason = "max_band_fade must be > 0";
  } else if (!(max_mirror_support > 0 && max_mirror_support <= 1)) {
    reason = "max_mirror_support must be in (0, 1]";
  }
  if (reason.empty()) return true;
  if (why != nullptr) *why = reason;
  return false;
}

BaseboardFeet TakeBothBaseboardFeet(const WallCheckInputs& in, const BaseboardFeetOptions& options,
                                    CorridorGeometry* geometry, RecoverDepthResult* result) {
  BaseboardFeet feet;
  if (!(options.same_ratio > 0) || !result->junctions.status.ok()) return feet;
  const double h = geometry->camera_height;
  const double before = CeilingDisagreement(result->ceiling, h);
  if (before > std::log(kCeilingSidesAgree)) return feet;  // One wall is wrong, not both alike.
  // Each junction's foot, in the search image; its band unlike the floor beyond it, and of one
  // colour from top to foot (a satin floor's reflection fades into the floor). The floor is
  // sampled only once both feet are found.
  JunctionPair pair = result->junctions;
  const double s = 1.0 / in.search.scale;
  MergedLine chosen[2], foot[2];
  double turn_deg[2] = {0, 0};
  for (int side = 0; side < 2; ++side) {
    const JunctionLine& line = side == 0 ? pair.left : pair.right;
    chosen[side] = LineThrough(line.near_end * s, line.far_end * s);
    if (!FindLowerEdge(in.search.bgr, 0, chosen[side], pair.vanishing_point * s, side == 0,
                       kBaseboardMaxTurnDeg, &foot[side], &turn_deg[side])) {
      return feet;
    }
  }
  const FloorAppearance floor = SampleFloor(in.search.bgr, 0);
  for (int side = 0; side < 2; ++side) {
    if (BandContrast(in.search.bgr, floor, chosen[side], foot[side], 0, 1) <
            options.min_band_contrast ||
        BandFade(in.search.bgr, chosen[side], foot[side], 0, 1) > options.max_band_fade) {
      return feet;
    }
  }
  for (int side = 0; side < 2; ++side) {
    JunctionLine& line = side == 0 ? pair.left : pair.right;
    foot[side].start *= in.search.scale;
    foot[side].end *= in.search.scale;
    TurnJunctionToFoot(foot[side], turn_deg[side], pair.vanishing_point, side == 0, &line);
    line.edge_points.clear();  // The solvers sample the turned lines.
    line.edge_weights.clear();
  }
  const RecoverDepthOptions& ro = in.options;
  const CorridorObservation observation = ObservationFromJunctions(pair, in.camera, ro);
  SolverSummary summary;
  if (!in.solver.Solve(observation, nullptr, &summary).ok()) return feet;
  CorridorGeometry g = summary.estimate;
  g.camera_height = in.camera.mount_height;
  if (!(g.LeftDistance() > 0) || !(g.RightDistance() > 0)) return feet;
  const double distance[2] = {geometry->LeftDistance(), geometry->RightDistance()};
  feet.ratio[0] = distance[0] / g.LeftDistance();
  feet.ratio[1] = distance[1] / g.RightDistance();
  if (std::abs(std::log(feet.ratio[0] / feet.ratio[1])) > std::log1p(options.same_ratio)) {
    return feet;
  }
  const double r = std::sqrt(feet.ratio[0] * feet.ratio[1]);
  const double b = h * (1 - 1 / r);
  if (b < options.min_height || b > options.max_height || !(r < 2)) return feet;
  // A reflection: the baseboard's top above the junction, where the mirrored band's foot puts it
  // (a reflected foot at d h / (h + b), its top at d h / (h - b) = d / (2 - r)).
  for (int side = 0; side < 2; ++side) {
    const double x = (side == 0 ? -1 : 1) * distance[side] / (2 - r);
    if (BestFloorLineSupportNear(in.search.bgr, in.search.camera, *geometry, x, 1.02, ro.ceiling,
                                 in.edges) > options.max_mirror_support) {
      return feet;
    }
  }
  if (!CheckPlausibleShape(g, ro).ok() || !CheckLineFit(g, observation, in.camera, ro).ok()) {
    return feet;
  }
  const Eigen::Vector3d vp = pair.left.line.cross(pair.right.line);
  if (std::abs(vp.z()) > 1e-12) pair.vanishing_point = vp.head<2>() / vp.z();
  result->junctions = pair;
  result->solver_summary = summary;
  g.ceiling_height = geometry->ceiling_height;
  *geometry = g;
  feet.taken = true;
  char note[240];
  std::snprintf(note, sizeof(note),
                "both junctions: the feet of the bands below the lines first taken (baseboards' "
                "tops), which move both walls in by one ratio (%.3f, %.3f): baseboards %.2f m high",
                feet.ratio[0], feet.ratio[1], b);
  result->AddNote(note);
  return feet;
}

}  // namespace corridor
