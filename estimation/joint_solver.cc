#include "estimation/joint_solver.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <type_traits>
#include <vector>

#include "estimation/bounded_lm.h"
#include "estimation/closed_form.h"
#include "estimation/junction_line_residual.h"

namespace corridor {
namespace {

// The JunctionLineResidual of every edge point, times the square root of its weight (the
// maximum-likelihood fit for points of variance 1 / weight): the left junction's points, then the
// right's. Prepare computes the two sides' lines once per x; each residual is then a point's
// distance from its side's line.
class JunctionResiduals {
 public:
  using Jet = ceres::Jet<double, 4>;
  JunctionResiduals(const CorridorObservation& observation, const FloorIntrinsics& intrinsics)
      : observation_(observation), intrinsics_(intrinsics) {}

  int size() const { return static_cast<int>(observation_.left.size() + observation_.right.size()); }

  bool Prepare(const double* x) const { return PrepareInto(x, lines_); }
  bool Prepare(const Jet* x) const { return PrepareInto(x, jet_lines_); }

  template <typename T>
  bool operator()(int i, const T* /*x, in the lines Prepare computed*/, T* residual) const {
    const int left = static_cast<int>(observation_.left.size());
    const int side = i < left ? -1 : 1;
    const size_t k = static_cast<size_t>(i < left ? i : i - left);
    const auto& p = side < 0 ? observation_.left[k] : observation_.right[k];
    *residual = JunctionLineResidual::Distance(intrinsics_, Lines<T>()[side < 0 ? 0 : 1], p.x(),
                                               p.y());
    const std::vector<double>& weights =
        side < 0 ? observation_.left_weights : observation_.right_weights;
    if (!weights.empty()) *residual *= std::sqrt(weights[k]);
    return true;
  }

 private:
  template <typename T>
  bool PrepareInto(const T* x, Vec3<T>* out) const {
    return JunctionLineResidual::ScaledLine(intrinsics_, x, -1, &out[0]) &&
           JunctionLineResidual::ScaledLine(intrinsics_, x, 1, &out[1]);
  }
  template <typename T>
  const Vec3<T>* Lines() const {
    if constexpr (std::is_same_v<T, double>) {
      return lines_;
    } else {
      return jet_lines_;
    }
  }

  const CorridorObservation& observation_;
  const FloorIntrinsics intrinsics_;
  mutable Vec3<double> lines_[2] = {};  // Prepare's, at the x of the residuals that follow.
  mutable Vec3<Jet> jet_lines_[2] = {};
};

// Each side's points within trim_sigmas robust standard deviations of the lines of x (at least
// kMinTrimPx), into *kept (whose vectors keep their memory) with their weights and *mask (1 =
// kept, the left side's points then the right's). Distances are weighted (sqrt(w) |r|, in units
// of one point of average noise). False, keeping nothing, when a side would keep fewer than two
// points.
bool TrimToFit(const CorridorObservation& all, const FloorIntrinsics& intrinsics, const double x[4],
               double trim_sigmas, CorridorObservation* kept, std::vector<char>* mask) {
  constexpr double kMinTrimPx = 1.0;
  thread_local std::vector<double> thread_distance, thread_sorted;
  std::vector<double>& distance = thread_distance;
  std::vector<double>& sorted = thread_sorted;
  mask->clear();
  kept->left.clear();
  kept->right.clear();
  kept->left_weights.clear();
  kept->right_weights.clear();
  for (int side = -1; side <= 1; side += 2) {
    const std::vector<Eigen::Vector2d>& points = side < 0 ? all.left : all.right;
    Vec3<double> line;
    if (!JunctionLineResidual::ScaledLine(intrinsics, x, side, &line)) return false;
    distance.clear();
    for (const auto& p : points) {
      const double r = JunctionLineResidual::Distance(intrinsics, line, p.x(), p.y());
      if (!std::isfinite(r)) return false;
      distance.push_back(std::abs(r) * std::sqrt(all.Weight(side, distance.size())));
    }
    sorted.assign(distance.begin(), distance.end());
    const size_t mid = sorted.size() / 2;
    std::nth_element(sorted.begin(), sorted.begin() + mid, sorted.end());
    const double threshold = std::max(trim_sigmas * 1.4826 * sorted[mid], kMinTrimPx);
    std::vector<Eigen::Vector2d>& out = side < 0 ? kept->left : kept->right;
    std::vector<double>& out_weights = side < 0 ? kept->left_weights : kept->right_weights;
    const bool weighted = !(side < 0 ? all.left_weights : all.right_weights).empty();
    int positive = 0;
    for (size_t i = 0; i < points.size(); ++i) {
      const bool keep = distance[i] <= threshold;
      mask->push_back(keep ? 1 : 0);
      if (!keep) continue;
      out.push_back(points[i]);
      if (weighted) out_weights.push_back(all.Weight(side, i));
      positive += all.Weight(side, i) > 0 ? 1 : 0;
    }
    if (positive < 2) return false;
  }
  return true;
}

}  // namespace

Status JointSolver::Solve(const CorridorObservation& observation, const CorridorGeometry* initial,
                          SolverSummary* summary) const {
  const auto start = std::chrono::steady_clock::now();
  *summary = SolverSummary();
  summary->solver_name = Name();
  std::string why;
  if (!observation.Check(&why)) return Status::InvalidArgument(why);
  CorridorGeometry start_geometry;
  if (initial != nullptr) {
    start_geometry = *initial;
  } else {
    const Status status = SolveClosedForm(observation, &start_geometry);
    if (!status.ok()) return status;
  }
  const LmOptions& lm = options_.lm;
  double x[4] = {std::clamp(start_geometry.yaw, -lm.max_abs_yaw, lm.max_abs_yaw),
                 std::clamp(start_geometry.pitch, -lm.max_abs_pitch, lm.max_abs_pitch),
                 start_geometry.offset,
                 start_geometry.width > 0.05 ? start_geometry.width : lm.initial_width};
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const double lower[4] = {-lm.max_abs_yaw, -lm.max_abs_pitch, -kInf, 0.05};
  const double upper[4] = {lm.max_abs_yaw, lm.max_abs_pitch, kInf, kInf};
  BoundedLmOptions lm_options;
  lm_options.max_iterations = lm.max_iterations;
  lm_options.function_tolerance = lm.function_tolerance;
  lm_options.parameter_tolerance = lm.parameter_tolerance;
  lm_options.gradient_tolerance = lm.gradient_tolerance;
  lm_options.loss = RobustLoss::FromName(options_.loss, options_.loss_scale);
  const FloorIntrinsics intrinsics{observation.fx, observation.fy, observation.cx, observation.cy,
                                   observation.camera_height};
  BoundedLmSummary lm_summary =
      SolveBoundedLm<4>(JunctionResiduals(observation, intrinsics), lm_options, lower, upper, x);
  summary->evaluations = lm_summary.residual_evaluations;
  summary->iterations = lm_summary.iterations;
  // Trimming: refit on the points near the fit's lines, which are chosen again from all points at
  // each new fit (a point dropped by a fit pulled off by others may come back), until they repeat.
  // The thread's, reused from call to call.
  thread_local CorridorObservation thread_kept;
  thread_local std::vector<char> thread_mask, thread_previous;
  CorridorObservation& kept = thread_kept;
  std::vector<char>& mask = thread_mask;
  std::vector<char>& previous = thread_previous;
  previous.assign(observation.left.size() + observation.right.size(), 1);
  constexpr int kMaxTrimRounds = 3;
  for (int round = 0; options_.trim_sigmas > 0 && round < kMaxTrimRounds &&
                      lm_summary.termination != BoundedLmSummary::Termination::kFailure;
       ++round) {
    if (!TrimToFit(observation, intrinsics, x, options_.trim_sigmas, &kept, &mask) ||
        mask == previous) {
      break;
    }
    previous.swap(mask);
    kept.fx = observation.fx;
    kept.fy = observation.fy;
    kept.cx = observation.cx;
    kept.cy = observation.cy;
    kept.camera_height = observation.camera_height;
    double refit[4] = {x[0], x[1], x[2], x[3]};
    const BoundedLmSummary trimmed =
        SolveBoundedLm<4>(JunctionResiduals(kept, intrinsics), lm_options, lower, upper, refit);
    summary->evaluations += trimmed.residual_evaluations;
    summary->iterations += trimmed.iterations;
    if (trimmed.termination == BoundedLmSummary::Termination::kFailure) break;
    lm_summary = trimmed;
    std::copy(refit, refit + 4, x);
  }
  summary->final_cost = lm_summary.final_cost;
  summary->converged = lm_summary.termination == BoundedLmSummary::Termination::kConvergence;
  summary->seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (lm_summary.termination == BoundedLmSummary::Termination::kFailure) {
    return Status::ImplausibleGeometry(std::string("joint solve failed: ") + lm_summary.message);
  }
  summary->estimate.yaw = x[0];
  summary->estimate.pitch = x[1];
  summary->estimate.offset = x[2];
  summary->estimate.width = x[3];
  summary->estimate.camera_height = observation.camera_height;
  return Status::Ok();
}

}  // namespace corridor
