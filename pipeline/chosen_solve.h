#pragma once

#include "corridor_depth/camera.h"
#include "corridor_depth/corridor_geometry.h"
#include "corridor_depth/junction_lines.h"
#include "corridor_depth/recover_depth.h"
#include "corridor_depth/solver.h"
#include "corridor_depth/status.h"

namespace corridor {

// The layout (which lines are the junctions, where the ceiling is) is decided with one fixed
// solve: `joint` on points sampled along the junction lines (LayoutOptions). The wall checks
// compare thresholds on what that solve gives, so a millimetre's difference between solvers
// would otherwise flip their decisions, and a solver comparison would measure the flips rather
// than the solvers. The solver the options name then estimates the four parameters from the
// final junctions, with the evidence the options name (ChosenSolve).

// The options with which the layout is solved: options.solver_evidence "lines" (solver and
// checks' thresholds otherwise as given).
RecoverDepthOptions LayoutOptions(const RecoverDepthOptions& options);

// The layout's solver: "joint".
const char* LayoutSolverName();

// True when the options' solver or evidence differ from the layout's, so that the final solve
// can give another answer.
bool ChosenSolveDiffers(const RecoverDepthOptions& options);

// `solver` (the options' own) on `junctions` (both found) with the options' evidence; on
// success *geometry takes its yaw, pitch, width and offset (its camera and ceiling heights stay)
// and *summary its report. A solve that fails, or an estimate CheckPlausibleShape or
// CheckLineFit refuses, leaves both untouched and returns why.
Status ChosenSolve(const CorridorSolver& solver, const RecoverDepthOptions& options,
                   const JunctionPair& junctions, const Camera& camera, CorridorGeometry* geometry,
                   SolverSummary* summary);

}  // namespace corridor
