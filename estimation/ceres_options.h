#pragma once

#include <ceres/solver.h>

#include "corridor_depth/solver_options.h"

namespace corridor {

// The Ceres settings every Levenberg-Marquardt solve here uses: dense QR on one thread, silent,
// with the iteration limit and tolerances of `lm`.
inline ceres::Solver::Options LevenbergMarquardtOptions(const LmOptions& lm) {
  ceres::Solver::Options options;
  options.minimizer_type = ceres::TRUST_REGION;
  options.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
  options.linear_solver_type = ceres::DENSE_QR;
  options.max_num_iterations = lm.max_iterations;
  options.function_tolerance = lm.function_tolerance;
  options.parameter_tolerance = lm.parameter_tolerance;
  options.gradient_tolerance = lm.gradient_tolerance;
  options.num_threads = 1;
  options.logging_type = ceres::SILENT;
  options.minimizer_progress_to_stdout = false;
  return options;
}

}  // namespace corridor
