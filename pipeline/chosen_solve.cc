#include "pipeline/chosen_solve.h"

#include "pipeline/plausibility.h"
#include "pipeline/solver_evidence.h"

namespace corridor {

RecoverDepthOptions LayoutOptions(const RecoverDepthOptions& options) {
  RecoverDepthOptions layout = options;
  layout.solver = LayoutSolverName();
  layout.solver_evidence = "lines";
  return layout;
}

const char* LayoutSolverName() { return "joint"; }

bool ChosenSolveDiffers(const RecoverDepthOptions& options) {
  return options.solver != LayoutSolverName() || SolverSeesEdges(options);
}

Status ChosenSolve(const CorridorSolver& solver, const RecoverDepthOptions& options,
                   const JunctionPair& junctions, const Camera& camera, CorridorGeometry* geometry,
                   SolverSummary* summary) {
  // The thread's observation, whose point vectors keep their memory from frame to frame.
  thread_local CorridorObservation observation;
  ObservationFromJunctions(junctions, camera, options, &observation);
  SolverSummary solved;
  Status status = solver.Solve(observation, nullptr, &solved);
  if (!status.ok()) {
    // Lines no solver can use are no corridor; a solver's own failure keeps its code.
    const std::string why = "the " + options.solver + " solver: " + status.message();
    return status.code() == StatusCode::kInvalidArgument ? Status::NoCorridorFound(why)
                                                         : Status(status.code(), why);
  }
  CorridorGeometry estimate = solved.estimate;
  estimate.camera_height = geometry->camera_height;
  estimate.ceiling_height = geometry->ceiling_height;
  estimate.end_distance = geometry->end_distance;
  status = CheckPlausibleShape(estimate, options);
  if (status.ok()) status = CheckLineFit(estimate, observation, camera, options);
  if (!status.ok()) return status;
  *geometry = estimate;
  *summary = solved;
  return Status::Ok();
}

}  // namespace corridor
