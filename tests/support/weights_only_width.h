#pragma once

// The relative width error of a solver given only the points' weights to go by: no robust loss
// and no trimming, so what the weights make of shifted or second-edge points shows in the width.

#include <cmath>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "corridor_depth/solver.h"

namespace corridor {
namespace testing {

inline double WeightsOnlyWidthError(const std::string& solver_name, const CorridorObservation& obs,
                                    const CorridorGeometry& truth,
                                    double max_weight_ratio = SolverOptions().max_weight_ratio) {
  SolverOptions options;
  options.loss = "none";
  options.trim_sigmas = 0;
  options.max_weight_ratio = max_weight_ratio;
  std::unique_ptr<CorridorSolver> solver;
  EXPECT_TRUE(CreateSolver(solver_name, options, &solver).ok());
  SolverSummary summary;
  const Status status = solver->Solve(obs, nullptr, &summary);
  EXPECT_TRUE(status.ok()) << solver_name << ": " << status.ToString();
  return std::abs(summary.estimate.width - truth.width) / truth.width;
}

}  // namespace testing
}  // namespace corridor
