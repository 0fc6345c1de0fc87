#include "corridor_depth/solver.h"

#include <chrono>
#include <vector>

#include "estimation/closed_form.h"
#include "estimation/grid_search_solver.h"
#include "estimation/joint_solver.h"
#include "estimation/lm_solver.h"

namespace corridor {
namespace {

// docs/geometry.md, section 4, behind the solver interface; ignores any initial estimate.
class ClosedFormSolver : public CorridorSolver {
 public:
  std::string Name() const override { return "closed_form"; }
  Status Solve(const CorridorObservation& observation, const CorridorGeometry* /*initial*/,
               SolverSummary* summary) const override {
    const auto start = std::chrono::steady_clock::now();
    *summary = SolverSummary();
    summary->solver_name = Name();
    const Status status = SolveClosedForm(observation, &summary->estimate);
    summary->evaluations = 1;
    summary->iterations = 1;
    summary->converged = status.ok();
    summary->seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return status;
  }
};

// Runs each solver from the previous one's estimate: "closed_form+lm".
class ChainedSolver : public CorridorSolver {
 public:
  explicit ChainedSolver(std::vector<std::unique_ptr<CorridorSolver>> stages)
      : stages_(std::move(stages)) {}

  std::string Name() const override {
    std::string name;
    for (const auto& stage : stages_) name += (name.empty() ? "" : "+") + stage->Name();
    return name;
  }

  Status Solve(const CorridorObservation& observation, const CorridorGeometry* initial,
               SolverSummary* summary) const override {
    const auto start = std::chrono::steady_clock::now();
    SolverSummary total;
    const CorridorGeometry* previous = initial;
    CorridorGeometry estimate;
    for (const auto& stage : stages_) {
      SolverSummary part;
      const Status status = stage->Solve(observation, previous, &part);
      total.evaluations += part.evaluations;
      total.iterations += part.iterations;
      if (!status.ok()) {
        *summary = total;
        summary->solver_name = Name();
        return Status(status.code(), stage->Name() + ": " + status.message());
      }
      estimate = part.estimate;
      previous = &estimate;
      total.final_cost = part.final_cost;
      total.converged = part.converged;
    }
    total.estimate = estimate;
    total.solver_name = Name();
    total.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    *summary = total;
    return Status::Ok();
  }

 private:
  std::vector<std::unique_ptr<CorridorSolver>> stages_;
};

}  // namespace

std::unique_ptr<CorridorSolver> CreateSolver(SolverType type, const SolverOptions& options) {
  switch (type) {
    case SolverType::kGridSearch:
      return std::make_unique<GridSearchSolver>(options);
    case SolverType::kClosedForm:
      return std::make_unique<ClosedFormSolver>();
    case SolverType::kLevenbergMarquardt:
      return std::make_unique<LmSolver>(options);
    case SolverType::kJoint:
      return std::make_unique<JointSolver>(options);
  }
  return nullptr;
}

Status CreateSolver(const std::string& name, const SolverOptions& options,
                    std::unique_ptr<CorridorSolver>* solver) {
  std::string why;
  std::vector<SolverType> chain;
  if (!ParseSolverChain(name, &chain, &why)) return Status::InvalidArgument(why);
  if (!options.Check(&why)) return Status::InvalidArgument("solver options: " + why);
  if (chain.size() == 1) {
    *solver = CreateSolver(chain.front(), options);
    return Status::Ok();
  }
  std::vector<std::unique_ptr<CorridorSolver>> stages;
  for (SolverType type : chain) stages.push_back(CreateSolver(type, options));
  *solver = std::make_unique<ChainedSolver>(std::move(stages));
  return Status::Ok();
}

}  // namespace corridor
