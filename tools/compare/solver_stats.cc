#include "tools/compare/solver_stats.h"

#include <cmath>

#include "corridor_depth/evaluation.h"

namespace corridor {

bool IsGrossFailure(const CorridorGeometry& e, const CorridorGeometry& t) {
  if (!std::isfinite(e.yaw) || !std::isfinite(e.pitch) || !std::isfinite(e.offset) ||
      !std::isfinite(e.width)) {
    return true;
  }
  return std::abs(e.width - t.width) > 0.25 * t.width || std::abs(e.yaw - t.yaw) > 0.1 ||
         std::abs(e.pitch - t.pitch) > 0.1;
}

void SolverCaseAccumulator::Add(const Status& status, const SolverSummary& summary,
                                const CorridorGeometry& truth) {
  ++trials_;
  seconds_.push_back(summary.seconds);
  evaluations_.push_back(summary.evaluations);
  if (!status.ok() || IsGrossFailure(summary.estimate, truth)) {
    ++failures_;
    return;
  }
  yaw_.push_back(std::abs(summary.estimate.yaw - truth.yaw));
  pitch_.push_back(std::abs(summary.estimate.pitch - truth.pitch));
  offset_.push_back(std::abs(summary.estimate.offset - truth.offset));
  width_.push_back(std::abs(summary.estimate.width - truth.width) / truth.width);
}

SolverCaseStats SolverCaseAccumulator::Finish(const std::string& solver,
                                              const std::string& case_name, double noise,
                                              double outliers) const {
  SolverCaseStats s;
  s.solver = solver;
  s.case_name = case_name;
  s.noise_px = noise;
  s.outlier_fraction = outliers;
  s.trials = trials_;
  s.failures = failures_;
  s.yaw_median = Percentile(yaw_, 50);
  s.yaw_p90 = Percentile(yaw_, 90);
  s.pitch_median = Percentile(pitch_, 50);
  s.pitch_p90 = Percentile(pitch_, 90);
  s.offset_median = Percentile(offset_, 50);
  s.offset_p90 = Percentile(offset_, 90);
  s.width_median = Percentile(width_, 50);
  s.width_p90 = Percentile(width_, 90);
  s.seconds_median = Percentile(seconds_, 50);
  s.evaluations_median = Percentile(evaluations_, 50);
  return s;
}

}  // namespace corridor
