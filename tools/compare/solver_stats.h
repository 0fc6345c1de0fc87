#pragma once

#include <string>
#include <vector>

#include "corridor_depth/corridor_geometry.h"
#include "corridor_depth/status.h"
#include "corridor_depth/solver.h"

namespace corridor {

// One solver's outcome on one case (a noise level and outlier fraction, or a dataset).
struct SolverCaseStats {
  std::string solver;                        // Solver name.
  std::string case_name;                     // E.g. "noise=1px outliers=10%" or "dataset".
  double noise_px = 0;                       // The case's noise, px (NaN for a dataset).
  double outlier_fraction = 0;               // The case's outlier fraction (NaN for a dataset).
  int trials = 0;                            // Solves attempted.
  int failures = 0;                          // Error status, non-finite, or a gross error (see IsGrossFailure).
  double yaw_median = 0, yaw_p90 = 0;        // |yaw error|, rad, over non-failed trials.
  double pitch_median = 0, pitch_p90 = 0;    // |pitch error|, rad.
  double offset_median = 0, offset_p90 = 0;  // |offset error|, m.
  double width_median = 0, width_p90 = 0;    // |width error| / true width.
  double seconds_median = 0;                 // Time per solve.
  double evaluations_median = 0;             // Cost evaluations or residual evaluations.
};

// Collects the trials of one solver on one case.
class SolverCaseAccumulator {
 public:
  void Add(const Status& status, const SolverSummary& summary, const CorridorGeometry& truth);
  SolverCaseStats Finish(const std::string& solver, const std::string& case_name, double noise,
                         double outliers) const;

 private:
  int trials_ = 0, failures_ = 0;
  std::vector<double> yaw_, pitch_, offset_, width_, seconds_, evaluations_;
};

// A solve that "succeeded" but is useless: width off by more than 25% or yaw/pitch off by more
// than 0.1 rad.
bool IsGrossFailure(const CorridorGeometry& estimate, const CorridorGeometry& truth);

}  // namespace corridor
