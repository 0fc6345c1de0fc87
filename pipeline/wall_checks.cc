#include "pipeline/wall_checks.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <Eigen/Geometry>

#include "perception/lower_edge.h"
#include "pipeline/ceiling_agreement.h"
#include "pipeline/ceiling_split.h"
#include "pipeline/far_wall_check.h"
#include "pipeline/frame_confidence.h"
#include "pipeline/inner_line_check.h"
#include "pipeline/plausibility.h"
#include "pipeline/solver_evidence.h"

namespace corridor {
namespace {

// How closely the two ceiling sides must agree with a foot taken.
constexpr double kFootCeilingAgreement = 0.03;

}  // namespace

bool SolveWallCheck(const WallCheckInputs& in, const JunctionPair& pair, CorridorGeometry* g,
                    SolverSummary* summary) {
  const CorridorObservation observation = ObservationFromJunctions(pair, in.camera, in.options);
  if (!in.solver.Solve(observation, nullptr, summary).ok()) return false;
  *g = summary->estimate;
  g->camera_height = in.camera.mount_height;
  return CheckPlausibleShape(*g, in.options).ok() &&
         CheckLineFit(*g, observation, in.camera, in.options).ok();
}

bool FindColourFoot(const WallCheckInputs& in, const JunctionPair& pair, int side,
                    MergedLine* chosen, MergedLine* foot, double* turn_deg) {
  const JunctionLine& line = side == 0 ? pair.left : pair.right;
  ColourFootMemo::Entry* kept =
      in.colour_feet != nullptr && (side == 0 || side == 1) ? &in.colour_feet->side[side] : nullptr;
  if (kept != nullptr && kept->valid && kept->line == line.line &&
      kept->near_end == line.near_end && kept->far_end == line.far_end &&
      kept->vanishing_point == pair.vanishing_point) {
    *chosen = kept->chosen;
    if (kept->found) *foot = kept->foot, *turn_deg = kept->turn_deg;
    return kept->found;
  }
  // The junction in search pixels, from its near end toward the vanishing point.
  const double s = 1.0 / in.search.scale;
  *chosen = LineThrough(line.near_end * s, line.far_end * s);
  const bool found = FindLowerEdge(in.search.bgr, 0, *chosen, pair.vanishing_point * s,
                                   side == 0, kBaseboardMaxTurnDeg, foot, turn_deg);
  if (kept != nullptr) {
    kept->valid = true;
    kept->line = line.line, kept->near_end = line.near_end, kept->far_end = line.far_end;
    kept->vanishing_point = pair.vanishing_point;
    kept->found = found;
    kept->chosen = *chosen;
    if (found) kept->foot = *foot, kept->turn_deg = *turn_deg;
  }
  return found;
}

void TurnToColourFoot(const WallCheckInputs& in, MergedLine foot, double turn_deg, int side,
                      JunctionPair* pair) {
  // Turned in raw pixels by the same angle (a uniform scale keeps angles), over the foot's extent.
  foot.start *= in.search.scale;
  foot.end *= in.search.scale;
  JunctionLine& line = side == 0 ? pair->left : pair->right;
  TurnJunctionToFoot(foot, turn_deg, pair->vanishing_point, side == 0, &line);
  line.edge_points.clear();  // The solvers sample the turned line: its edge may be faint.
  line.edge_weights.clear();
}

Status SearchCeiling(const WallCheckInputs& in, CorridorGeometry* geometry,
                     CeilingEstimate* estimate) {
  const Status status = DetectCeiling(in.search.bgr, in.search.camera, *geometry,
                                      in.options.ceiling, estimate, in.edges);
  if (status.ok()) {
    geometry->ceiling_height = estimate->found ? estimate->height : in.options.ceiling_height;
  }
  return status;
}

bool CheckBaseboards(const WallCheckInputs& in, CorridorGeometry* geometry,
                     RecoverDepthResult* result) {
  const RecoverDepthOptions& options = in.options;
  // Heights that agree within 6% need no check; a lower line must bring them within 8%, and to
  // less than half the disagreement.
  // Without two sides strong enough to compare (as when the upper line has skewed the whole
  // geometry, so that neither ceiling junction is where it is sought), a lower line must find
  // both, each with the ceiling search's own minimum support, agreeing within 3%: two weak
  // searches that agree that closely do not do so by chance.
  const double agree = std::log(kCeilingSidesAgree), accept = std::log(1.08),
               weak_accept = std::log(1.03);
  const double before = CeilingDisagreement(result->ceiling, geometry->camera_height);
  if (before >= 0 && before <= agree) return false;
  const bool compared = before >= 0;
  // A lower line must also halve `best` (the disagreement so far); without a comparison it starts
  // at twice weak_accept, so that only the weak_accept bound applies to the first one.
  double best = compared ? before : 2 * weak_accept;
  int best_side = -1;
  CorridorGeometry best_geometry;
  SolverSummary best_summary;
  CeilingEstimate best_ceiling;
  for (int side = 0; side < 2; ++side) {
    const JunctionPair& found = result->junctions;
    if (!(side == 0 ? found.has_left_lower : found.has_right_lower)) continue;
    JunctionPair pair = result->junctions;
    (side == 0 ? pair.left : pair.right) = side == 0 ? pair.left_lower : pair.right_lower;
    SolverSummary summary;
    CorridorGeometry g;
    if (!SolveWallCheck(in, pair, &g, &summary)) continue;
    CeilingEstimate ceiling;
    if (!DetectCeiling(in.search.bgr, in.search.camera, g, options.ceiling, &ceiling, in.edges)
             .ok()) {
      continue;
    }
    const double after =
        compared ? CeilingDisagreement(ceiling, g.camera_height)
                 : CeilingDisagreement(ceiling, g.camera_height, options.ceiling.min_support);
    if (after < 0 || after > (compared ? accept : weak_accept) || after > 0.5 * best) continue;
    best = after;
    best_side = side;
    best_geometry = g;
    best_summary = summary;
    best_ceiling = ceiling;
  }
  if (best_side < 0) return false;
  JunctionPair& pair = result->junctions;
  if (best_side == 0) {
    pair.left = pair.left_lower;
  } else {
    pair.right = pair.right_lower;
  }
  const Eigen::Vector3d vp = pair.left.line.cross(pair.right.line);
  if (std::abs(vp.z()) > 1e-12) pair.vanishing_point = vp.head<2>() / vp.z();
  result->solver_summary = best_summary;
  result->ceiling = best_ceiling;
  best_geometry.ceiling_height = best_ceiling.height;
  *geometry = best_geometry;
  result->AddNote(std::string(best_side == 0 ? "left" : "right") +
                  " junction: the lower of two parallel lines (the upper one a baseboard's "
                  "top or a recess's floor line), with which both ceiling junctions agree");
  return true;
}

bool TakeFootOfSplitWall(const WallCheckInputs& in, CorridorGeometry* geometry,
                         RecoverDepthResult* result) {
  const RecoverDepthOptions& options = in.options;
  const CeilingEstimate& ceiling = result->ceiling;
  if (CeilingSplit(in.search.bgr, in.search.camera, *geometry, ceiling, options.ceiling,
                   options.ceiling_split, in.edges) < 0) {
    return false;
  }
  // The wall put too far (on a baseboard's top) has the higher ceiling side.
  const double h = geometry->camera_height;
  const int side = ceiling.side_height[0] - h > ceiling.side_height[1] - h ? 0 : 1;
  const bool left = side == 0;
  JunctionPair pair = result->junctions;
  MergedLine chosen, foot;
  double turn_deg = 0;
  if (!FindColourFoot(in, pair, side, &chosen, &foot, &turn_deg)) return false;
  TurnToColourFoot(in, foot, turn_deg, side, &pair);
  SolverSummary summary;
  CorridorGeometry g;
  if (!SolveWallCheck(in, pair, &g, &summary)) return false;
  CeilingEstimate moved;
  if (!DetectCeiling(in.search.bgr, in.search.camera, g, options.ceiling, &moved, in.edges).ok()) {
    return false;
  }
  const double after = CeilingDisagreement(moved, g.camera_height, options.ceiling.min_support);
  if (after < 0 || after > std::log(1 + kFootCeilingAgreement)) return false;
  result->junctions = pair;
  result->solver_summary = summary;
  result->ceiling = moved;
  g.ceiling_height = moved.height;
  *geometry = g;
  result->AddNote(std::string(left ? "left" : "right") +
                  " junction: the foot of a band below the line first taken (a baseboard's top, "
                  "its foot too faint for a line), with which both ceiling junctions agree");
  return true;
}

namespace {

// Whether the frame with its wall moved is confident on its own evidence (its confidence, as the
// frame would report it, at least min_confidence): the previous frames' width may then not veto
// the move. A sequence overrules only a frame whose own evidence is weak.
bool MovedWallConfident(const WallCheckInputs& in, const CorridorGeometry& moved,
                        const CeilingEstimate& ceiling, int moved_side,
                        const JunctionPair& junctions) {
  const RecoverDepthOptions& options = in.options;
  const double split = CeilingSplit(in.search.bgr, in.search.camera, moved, ceiling,
                                    options.ceiling, options.ceiling_split, in.edges);
  const FrameEvidence evidence = GatherFrameEvidence(
      junctions, in.search, moved, CeilingDisagreement(ceiling, moved.camera_height),
      /*corrected=*/false, moved_side, options.vertical_crossings, split);
  return FrameConfidence(evidence) >= options.min_confidence;
}

}  // namespace

Status MoveInnerWall(const WallCheckInputs& in, const CorridorGeometry* previous,
                     CorridorGeometry* geometry, RecoverDepthResult* result) {
  const RecoverDepthOptions& options = in.options;
  // Both ceiling junctions found where the walls put them, agreeing: nothing to check. Neither
  // found: no side to trust (the trusted one must be in the ceiling search's range).
  const CeilingEstimate& found = result->ceiling;
  const double disagreement = CeilingDisagreement(found, geometry->camera_height);
  if ((disagreement >= 0 &&
       disagreement <= std::log(1 + MinInnerLineDisagreement(options.inner_line))) ||
      std::max(found.side_visible_support[0], found.side_visible_support[1]) <
          options.inner_line.min_support) {
    return Status::Ok();
  }
  CorridorGeometry moved = *geometry;
  InnerLineCheck check =
      CheckInnerLine(in.search.bgr, in.search.camera, options.ceiling, options.inner_line, &moved,
                     in.edges, {result->junctions.has_left_lower, result->junctions.has_right_lower},
                     {result->junctions.at_reflected_band[0], result->junctions.at_reflected_band[1]});
  if (!check.moved) {
    check = CheckFarWall(in.search.bgr, in.search.camera, options.ceiling, options.inner_line,
                         found, &moved, in.edges);
  }
  if (!check.moved || !CheckPlausibleShape(moved, options).ok()) return Status::Ok();
  CeilingEstimate ceiling;
  const Status status = SearchCeiling(in, &moved, &ceiling);
  if (!status.ok()) return status;
  // In a sequence the previous frame's width must agree better with the moved wall than with the
  // line it replaces (a misjudged side would otherwise carry on through the width hold), unless
  // the frame with the wall moved is confident on its own (MovedWallConfident), or the moved
  // walls' two ceiling sides, each searched alone, agree with each other and with the
  // trusted ceiling (within max_ceiling_change): the frame's own evidence confirms both walls, and
  // the recent width (from frames whose sides disagreed) is the wrong one. Sides agreeing on
  // another height are both walls wrong alike (ScaleWallsToCeiling), no confirmation.
  const double h = moved.camera_height;
  const double moved_disagreement = CeilingDisagreement(ceiling, h);
  bool confirmed = moved_disagreement >= 0 && moved_disagreement <= std::log(kCeilingSidesAgree);
  if (confirmed && previous != nullptr && previous->HasCeiling()) {
    confirmed = ceiling.height > h &&
                std::abs(std::log((ceiling.height - h) / (previous->ceiling_height - h))) <=
                    std::log(1 + options.max_ceiling_change);
  }
  if (previous != nullptr && previous->width > 0 && !confirmed &&
      std::abs(std::log(moved.width / previous->width)) >=
          std::abs(std::log(geometry->width / previous->width)) &&
      !MovedWallConfident(in, moved, ceiling, check.side, result->junctions)) {
    return Status::Ok();
  }
  result->ceiling = ceiling;
  *geometry = moved;
  result->moved_side = check.side;
  result->AddNote(DescribeInnerLineCheck(check));
  return Status::Ok();
}

}  // namespace corridor
