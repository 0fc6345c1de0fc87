#pragma once

#include "corridor_depth/camera.h"
#include "corridor_depth/corridor_geometry.h"
#include "corridor_depth/status.h"
#include "corridor_depth/solver.h"
#include "perception/ceiling_detector.h"
#include "perception/line_segments.h"
#include "perception/oriented_edges.h"
#include "perception/working_image.h"
#include "corridor_depth/recover_depth.h"

namespace corridor {

// The colour feet (FindColourFoot) found below the frame's junctions, per side, kept for the
// checks that look below the same line again.
struct ColourFootMemo {
  struct Entry {
    bool valid = false;
    Eigen::Vector3d line = Eigen::Vector3d::Zero();  // The junction and vanishing point looked from.
    Eigen::Vector2d near_end = Eigen::Vector2d::Zero(), far_end = Eigen::Vector2d::Zero();
    Eigen::Vector2d vanishing_point = Eigen::Vector2d::Zero();
    bool found = false;  // What FindColourFoot gave.
    MergedLine chosen, foot;
    double turn_deg = 0;
  };
  Entry side[2];
};

// The wall corrections that the ceiling's evidence allows (beyond the paper), run by
// DepthRecoverer::Reconstruct after the solver. They work on the frame's search image (the frame
// halved to search_max_width) and share its edges and colour feet.
struct WallCheckInputs {
  const RecoverDepthOptions& options;     // The layout's options (chosen_solve.h: evidence "lines").
  const CorridorSolver& solver;           // The layout's solver (the baseboard check solves again).
  const Camera& camera;                   // The frame's camera at full resolution.
  const WorkingImage& search;             // The search image and its camera.
  ImageEdges* edges;                      // The search image's edges, computed on demand and shared.
  ColourFootMemo* colour_feet = nullptr;  // The frame's colour feet, when shared (else none kept).
};

// The layout's solve of `pair` into *summary and *g (the camera's mount height set): false when
// the solve fails or its estimate is implausible (CheckPlausibleShape, CheckLineFit).
bool SolveWallCheck(const WallCheckInputs& in, const JunctionPair& pair, CorridorGeometry* g,
                    SolverSummary* summary);

// The lower edge of the band below the junction of `side` (0 left, 1 right) of `pair`, found by
// its colours (FindLowerEdge, within kBaseboardMaxTurnDeg) in the search image: the junction
// there into *chosen, the edge into *foot, its turn into *turn_deg. False when there is none.
bool FindColourFoot(const WallCheckInputs& in, const JunctionPair& pair, int side,
                    MergedLine* chosen, MergedLine* foot, double* turn_deg);

// The junction of `side` of *pair turned to `foot` (search pixels, as FindColourFoot gives it) by
// `turn_deg` in raw pixels, over the foot's extent; the solvers then sample the turned line (its
// edge points cleared).
void TurnToColourFoot(const WallCheckInputs& in, MergedLine foot, double turn_deg, int side,
                      JunctionPair* pair);

// The ceiling search for the walls of *geometry into *estimate; the geometry's ceiling height
// becomes the one found (options.ceiling_height when none is).
Status SearchCeiling(const WallCheckInputs& in, CorridorGeometry* geometry,
                     CeilingEstimate* estimate);

// ceiling_checks_baseboards: when both ceiling junctions were searched alone and disagree (or were
// too weak to compare), and a side has a lower parallel line, the geometry and ceiling with that
// line instead, if they make the two agree. Updates *geometry and *result (junctions, solver
// summary, ceiling, note). True when a lower line was taken.
bool CheckBaseboards(const WallCheckInputs& in, CorridorGeometry* geometry,
                     RecoverDepthResult* result);

// ceiling_checks_baseboards, when the two ceiling sides split (ceiling_split.h: each plainly seen,
// no one height fits both) and no lower line was taken: the wall whose ceiling side is the higher
// may stand on a baseboard's top whose foot is too faint for a line (a dark baseboard on a dark
// floor). The band's lower edge from the colours (FindLowerEdge) below that wall's junction is
// taken when, with it, both ceiling sides are found (each with the ceiling search's minimum
// support) and agree within 3%. Updates *geometry and *result as CheckBaseboards; true when taken.
bool TakeFootOfSplitWall(const WallCheckInputs& in, CorridorGeometry* geometry,
                         RecoverDepthResult* result);

// ceiling_checks_inner_lines: unless both ceiling junctions agree already, the inner-line check
// (inner_line_check.h), then, when it moves nothing, the far-wall check (far_wall_check.h); a
// moved wall updates *geometry, the ceiling, result->moved_side and the
// note. In a sequence (`previous` not null) the move must bring the width nearer the previous
// frame's. Fails only when the ceiling search does.
Status MoveInnerWall(const WallCheckInputs& in, const CorridorGeometry* previous,
                     CorridorGeometry* geometry, RecoverDepthResult* result);

}  // namespace corridor
