#include "pipeline/baseboard_feet.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <Eigen/Geometry>

#include "perception/appearance.h"
#include "perception/ceiling_detector.h"
#include "pipeline/ceiling_agreement.h"

namespace corridor {

bool BaseboardFeetOptions::Check(std::string* why) const {
  std::string reason;
  if (!(same_ratio >= 0 && same_ratio < 1)) {
    reason = "same_ratio must be in [0, 1) (0 = off)";
  } else if (!(ceiling_ratio >= 0 && ceiling_ratio < 1)) {
    reason = "ceiling_ratio must be in [0, 1) (0 = off)";
  } else if (!(min_height > 0 && max_height > min_height && std::isfinite(max_height))) {
    reason = "min_height must be > 0 m and max_height above it";
  } else if (!(min_band_contrast >= 0 && std::isfinite(min_band_contrast))) {
    reason = "min_band_contrast must be >= 0";
  } else if (!(max_band_fade > 0 && std::isfinite(max_band_fade))) {
    reason = "max_band_fade must be > 0";
  } else if (!(max_mirror_support > 0 && max_mirror_support <= 1)) {
    reason = "max_mirror_support must be in (0, 1]";
  } else if (!(min_across_support >= 0 && min_across_support <= 1)) {
    reason = "min_across_support must be in [0, 1] (0 = off)";
  } else if (!(max_above_support >= 0 && max_above_support < 1)) {
    reason = "max_above_support must be in [0, 1)";
  }
  if (reason.empty()) return true;
  if (why != nullptr) *why = reason;
  return false;
}

namespace {

// The pair with the junctions of `sides` (left, right) turned to the feet of the bands below them
// (FindLowerEdge in the search image), each band unlike the floor beyond it and of one colour top
// to foot; false when a side has no such foot. The floor is sampled only once the feet are found.
bool TurnToFeet(const WallCheckInputs& in, const BaseboardFeetOptions& options,
                const bool sides[2], JunctionPair* pair) {
  MergedLine chosen[2], foot[2];
  double turn_deg[2] = {0, 0};
  for (int side = 0; side < 2; ++side) {
    if (sides[side] &&
        !FindColourFoot(in, *pair, side, &chosen[side], &foot[side], &turn_deg[side])) {
      return false;
    }
  }
  const FloorAppearance floor = SampleFloor(in.search.bgr, 0);
  for (int side = 0; side < 2; ++side) {
    if (sides[side] &&
        (BandContrast(in.search.bgr, floor, chosen[side], foot[side], 0, 1) <
             options.min_band_contrast ||
         BandFade(in.search.bgr, chosen[side], foot[side], 0, 1) > options.max_band_fade)) {
      return false;
    }
  }
  for (int side = 0; side < 2; ++side) {
    if (sides[side]) TurnToColourFoot(in, foot[side], turn_deg[side], side, pair);
  }
  return true;
}

// The geometry solved from `pair` into *g and *summary (SolveWallCheck), with each wall's
// distance in `geometry` over its distance in *g into ratio; false when the solve fails.
bool SolveFeet(const WallCheckInputs& in, const JunctionPair& pair,
               const CorridorGeometry& geometry, CorridorGeometry* g, SolverSummary* summary,
               double ratio[2]) {
  if (!SolveWallCheck(in, pair, g, summary) || !(g->LeftDistance() > 0) ||
      !(g->RightDistance() > 0)) {
    return false;
  }
  ratio[0] = geometry.LeftDistance() / g->LeftDistance();
  ratio[1] = geometry.RightDistance() / g->RightDistance();
  return true;
}

// The foot of wall `far`'s band alone (TurnToFeet, *pair turned to it), solved into *g and
// *summary with each wall's ratio (SolveFeet): false unless found, the other wall stays (within
// same_ratio) and the wall moves in by less than 2.
bool OneWallFoot(const WallCheckInputs& in, const BaseboardFeetOptions& options,
                 const CorridorGeometry& geometry, int far, JunctionPair* pair, CorridorGeometry* g,
                 SolverSummary* summary, double ratio[2]) {
  const bool sides[2] = {far == 0, far == 1};
  return TurnToFeet(in, options, sides, pair) &&
         SolveFeet(in, *pair, geometry, g, summary, ratio) &&
         std::abs(std::log(ratio[1 - far])) <= std::log1p(options.same_ratio) && ratio[far] < 2;
}

// Whether a line stands above the junction of `side` where the top of a baseboard mirrored into
// a band of ratio r would (a reflected foot at d h / (h + b), its top at d h / (h - b) =
// d / (2 - r)), on edges over max_mirror_support of its view.
bool ReflectionAbove(const WallCheckInputs& in, const BaseboardFeetOptions& options,
                     const CorridorGeometry& geometry, int side, double r) {
  const double d = side == 0 ? geometry.LeftDistance() : geometry.RightDistance();
  const double x = (side == 0 ? -1 : 1) * d / (2 - r);
  return BestFloorLineSupportNear(in.search.bgr, in.search.camera, geometry, x, 1.02,
                                  in.options.ceiling, in.edges) > options.max_mirror_support;
}

// The best CorridorLineSupport of the top of a band b high on wall `side` of g, over heights
// b (1 -+ 0.1): b is measured through the foot's ratio.
double BandTopSupport(const WallCheckInputs& in, const CorridorGeometry& g, int side, double b) {
  const double x = side == 0 ? -g.LeftDistance() : g.RightDistance();
  double best = 0;
  for (int k = -4; k <= 4; ++k) {
    best = std::max(best, CorridorLineSupport(in.search.bgr, in.search.camera, g, x,
                                              g.camera_height - b * (1 + 0.025 * k),
                                              in.options.ceiling, in.edges));
  }
  return best;
}

// Takes the feet's pair and geometry into *result and *geometry, with `note`.
void TakeFeet(const JunctionPair& feet_pair, const SolverSummary& summary, CorridorGeometry g,
              const std::string& note, CorridorGeometry* geometry, RecoverDepthResult* result) {
  JunctionPair pair = feet_pair;
  const Eigen::Vector3d vp = pair.left.line.cross(pair.right.line);
  if (std::abs(vp.z()) > 1e-12) pair.vanishing_point = vp.head<2>() / vp.z();
  result->junctions = pair;
  result->solver_summary = summary;
  g.ceiling_height = geometry->ceiling_height;
  *geometry = g;
  result->AddNote(note);
}

}  // namespace

BaseboardFeet TakeBothBaseboardFeet(const WallCheckInputs& in, const BaseboardFeetOptions& options,
                                    CorridorGeometry* geometry, RecoverDepthResult* result) {
  BaseboardFeet feet;
  if (!(options.same_ratio > 0) || !result->junctions.status.ok()) return feet;
  const double h = geometry->camera_height;
  const double before = CeilingDisagreement(result->ceiling, h);
  if (before > std::log(kCeilingSidesAgree)) return feet;  // One wall is wrong, not both alike.
  JunctionPair pair = result->junctions;
  const bool both[2] = {true, true};
  CorridorGeometry g;
  SolverSummary summary;
  if (!TurnToFeet(in, options, both, &pair) ||
      !SolveFeet(in, pair, *geometry, &g, &summary, feet.ratio) ||
      std::abs(std::log(feet.ratio[0] / feet.ratio[1])) > std::log1p(options.same_ratio)) {
    return feet;
  }
  const double r = std::sqrt(feet.ratio[0] * feet.ratio[1]);
  const double b = h * (1 - 1 / r);
  if (b < options.min_height || b > options.max_height || !(r < 2) ||
      ReflectionAbove(in, options, *geometry, 0, r) ||
      ReflectionAbove(in, options, *geometry, 1, r)) {
    return feet;
  }
  char note[240];
  std::snprintf(note, sizeof(note),
                "both junctions: the feet of the bands below the lines first taken (baseboards' "
                "tops), which move both walls in by one ratio (%.3f, %.3f): baseboards %.2f m high",
                feet.ratio[0], feet.ratio[1], b);
  TakeFeet(pair, summary, g, note, geometry, result);
  feet.taken = true;
  return feet;
}

BaseboardFeet TakeOneBaseboardFoot(const WallCheckInputs& in, const BaseboardFeetOptions& options,
                                   CorridorGeometry* geometry, RecoverDepthResult* result) {
  BaseboardFeet feet;
  if (!(options.ceiling_ratio > 0) || !result->junctions.status.ok()) return feet;
  const double h = geometry->camera_height;
  const CeilingEstimate& ceiling = result->ceiling;
  if (CeilingDisagreement(ceiling, h, in.options.ceiling.min_support) < 0) return feet;
  // The wall on its baseboard's top has the higher ceiling side, by h / (h - b).
  const double above[2] = {ceiling.side_height[0] - h, ceiling.side_height[1] - h};
  const int far = above[0] > above[1] ? 0 : 1;
  const double factor = above[far] / above[1 - far];
  const double b_ceiling = h * (1 - 1 / factor);
  if (b_ceiling < options.min_height || b_ceiling > options.max_height) return feet;
  JunctionPair pair = result->junctions;
  CorridorGeometry g;
  SolverSummary summary;
  if (!OneWallFoot(in, options, *geometry, far, &pair, &g, &summary, feet.ratio)) return feet;
  // Two measures of one ratio: the foot's and the ceiling sides'.
  const double r = feet.ratio[far];
  if (std::abs(std::log(r / factor)) > std::log1p(options.ceiling_ratio) ||
      ReflectionAbove(in, options, *geometry, far, r)) {
    return feet;
  }
  char note[240];
  std::snprintf(note, sizeof(note),
                "%s junction: the foot of the band below the line first taken (a baseboard's "
                "top), which moves its wall in by %.3f, as its ceiling side's height over the "
                "other's (%.3f): a baseboard %.2f m high",
                far == 0 ? "left" : "right", r, factor, h * (1 - 1 / r));
  TakeFeet(pair, summary, g, note, geometry, result);
  feet.taken = true;
  return feet;
}

BaseboardFeet TakeFootShownAcross(const WallCheckInputs& in, const BaseboardFeetOptions& options,
                                  CorridorGeometry* geometry, RecoverDepthResult* result) {
  BaseboardFeet feet;
  if (!(options.min_across_support > 0) || !result->junctions.status.ok()) return feet;
  const double h = geometry->camera_height;
  int taken = -1;
  JunctionPair taken_pair;
  CorridorGeometry taken_g;
  SolverSummary taken_summary;
  double taken_r = 0, taken_across = 0;
  for (int far = 0; far < 2; ++far) {
    JunctionPair pair = result->junctions;
    CorridorGeometry g;
    SolverSummary summary;
    double ratio[2];
    if (!OneWallFoot(in, options, *geometry, far, &pair, &g, &summary, ratio)) continue;
    const double r = ratio[far];
    const double b = h * (1 - 1 / r);
    // The wall moved had no band above its line first taken (a line at its foot would), and the
    // other wall shows the band's top at the foot's height.
    if (b < options.min_height || b > options.max_height ||
        ReflectionAbove(in, options, *geometry, far, r) ||
        BandTopSupport(in, *geometry, far, b) > options.max_above_support) {
      continue;
    }
    const double across = BandTopSupport(in, g, 1 - far, b);
    if (across < options.min_across_support) continue;
    if (taken >= 0) return feet;  // Either wall could be on its top: neither is told.
    taken = far;
    taken_pair = pair;
    taken_g = g;
    taken_summary = summary;
    taken_r = r;
    taken_across = across;
  }
  if (taken < 0) return feet;
  feet.ratio[taken] = taken_r;
  char note[240];
  std::snprintf(note, sizeof(note),
                "%s junction: the foot of the band below the line first taken (a baseboard's "
                "top), whose top the other wall shows at the same height (%.2f m, on edges over "
                "%.2f of its view)",
                taken == 0 ? "left" : "right", h * (1 - 1 / taken_r), taken_across);
  TakeFeet(taken_pair, taken_summary, taken_g, note, geometry, result);
  feet.taken = true;
  return feet;
}

}  // namespace corridor
