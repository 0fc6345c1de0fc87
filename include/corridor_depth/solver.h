#pragma once

#include <memory>
#include <string>

#include "corridor_depth/corridor_geometry.h"
#include "corridor_depth/status.h"
#include "corridor_depth/corridor_observation.h"
#include "corridor_depth/solver_options.h"

namespace corridor {

// What every solver reports.
struct SolverSummary {
  CorridorGeometry estimate;  // Yaw, pitch, offset, width; camera_height copied from the input.
  double final_cost = 0;      // The last stage's cost (solver-specific units, pixels-based).
  int evaluations = 0;        // Cost-functor evaluations (grid) or residual evaluations (lm).
  int iterations = 0;         // Alternation rounds (grid, lm) or 1 (closed_form).
  double seconds = 0;         // Wall time of Solve.
  bool converged = false;     // True when the solver reached its own stopping criterion.
  std::string solver_name;    // E.g. "closed_form+lm".
};

// A solver fits the corridor model to one observation. Implementations are stateless and
// thread-safe: Solve may be called concurrently.
class CorridorSolver {
 public:
  virtual ~CorridorSolver() = default;
  virtual std::string Name() const = 0;
  // `initial` may be null; then the solver starts from its own prior.
  virtual Status Solve(const CorridorObservation& observation, const CorridorGeometry* initial,
                       SolverSummary* summary) const = 0;
};

// One solver of the given type.
std::unique_ptr<CorridorSolver> CreateSolver(SolverType type, const SolverOptions& options);

// A solver from a name such as "grid" or "closed_form+lm". Checks the options first; an unknown
// name is an InvalidArgument that lists the valid names.
Status CreateSolver(const std::string& name, const SolverOptions& options,
                    std::unique_ptr<CorridorSolver>* solver);

}  // namespace corridor
