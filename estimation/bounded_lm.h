#pragma once

// A Levenberg-Marquardt for a few parameters (N, fixed) with box bounds and a robust loss, over
// scalar residuals differentiated with ceres::Jet: all of its state lives on the stack, so a solve
// allocates nothing. It takes the steps Ceres's trust-region minimizer takes with
// LEVENBERG_MARQUARDT, DENSE_QR, Jacobi scaling and bounds (Solver::Options defaults otherwise):
// the column scaling fixed at the start point, the LM diagonal D^2 = diag(J'J) / radius, the
// radius updates, the projected Armijo line search of bounded problems, the same stopping tests
// and the same cost (1/2 sum rho(r^2)), so it stops where a Ceres solve of the same problem stops.
//
// Residuals: `int size() const` and `template <typename T> bool operator()(int i, const T* x,
// T* r) const` (false: residual i cannot be evaluated at x). Optionally `template <typename T>
// bool Prepare(const T* x) const`, called before residuals at a new x are evaluated, for the work
// they all share (false: x cannot be evaluated), and `bool Linearize(const RobustLoss&, const
// double* x, bounded_lm::Linearization<N>*) const`, the normal equations at x by a way of its
// own instead of a Jet per residual (false: x cannot be evaluated).

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>
#include <utility>

#include <ceres/jet.h>

#include "estimation/line_search_step.h"
#include "estimation/robust_loss.h"

namespace corridor {

struct BoundedLmOptions {
  int max_iterations = 50;
  double function_tolerance = 1e-6;
  double parameter_tolerance = 1e-8;
  double gradient_tolerance = 1e-10;
  RobustLoss loss;
};

struct BoundedLmSummary {
  enum class Termination {
    kConvergence,
    kNoConvergence,
    kFailure,
  };
  Termination termination = Termination::kFailure;
  const char* message = "";
  int residual_evaluations = 0;  // Cost-only evaluations (Ceres's num_residual_evaluations).
  int jacobian_evaluations = 0;  // With derivatives (Ceres's num_jacobian_evaluations).
  int iterations = 0;            // Ceres's Summary::iterations.size(): iteration 0 included.
  double initial_cost = 0, final_cost = 0;
};

namespace bounded_lm {

// Ceres's Solver::Options defaults for what BoundedLmOptions does not set.
constexpr double kInitialRadius = 1e4, kMaxRadius = 1e16, kMinRadius = 1e-32;
constexpr double kMinRelativeDecrease = 1e-3, kMinDiagonal = 1e-6, kMaxDiagonal = 1e32;
constexpr int kMaxInvalidSteps = 5;
constexpr double kSufficientDecrease = 1e-4, kMaxContraction = 1e-3, kMinContraction = 0.6;
constexpr double kMinLineStep = 1e-9;
constexpr int kMaxLineIterations = 20;

// The loss-corrected residuals and Jacobian at one point, reduced to what the solver needs: the
// cost, the gradient J'f, the squared column norms of J and the triangular factor R of J = QR
// with Q'f beside it (column N), accumulated one row at a time by Givens rotations.
template <int N>
struct Linearization {
  bool ok = false;
  double x[N] = {};
  double cost = 0;
  double gradient[N] = {};
  double column_sq[N] = {};
  double r[N][N + 1] = {};
};

// Rotates the row a (N entries and a right-hand side) into the triangular system r.
template <int N>
void AddRow(double (*r)[N + 1], double* a) {
  for (int k = 0; k < N; ++k) {
    if (a[k] == 0) continue;
    if (r[k][k] == 0) {
      for (int j = k; j <= N; ++j) std::swap(r[k][j], a[j]);
      return;
    }
    const double h = std::hypot(r[k][k], a[k]), c = r[k][k] / h, s = a[k] / h;
    for (int j = k; j <= N; ++j) {
      const double t = c * r[k][j] + s * a[j];
      a[j] = c * a[j] - s * r[k][j];
      r[k][j] = t;
    }
  }
}

// Ceres's residual-block treatment of a robust loss for one scalar residual (Triggs' correction,
// which reduces to the square root of rho' when rho'' <= 0): the cost term, and the factors
// applied to the residual and to its derivatives.
inline void Correct(const RobustLoss& loss, double residual, double* cost, double* residual_scale,
                    double* jacobian_scale) {
  const double s = residual * residual;
  if (loss.kind() == RobustLoss::Kind::kNone) {
    *cost = 0.5 * s;
    *residual_scale = *jacobian_scale = 1.0;
    return;
  }
  double rho[3] = {s, 1.0, 0.0};
  loss.Evaluate(s, rho);
  *cost = 0.5 * rho[0];
  const double sqrt_rho1 = std::sqrt(rho[1]);
  if (s == 0.0 || rho[2] <= 0.0) {
    *residual_scale = *jacobian_scale = sqrt_rho1;
    return;
  }
  const double alpha = 1.0 - std::sqrt(1.0 + 2.0 * s * rho[2] / rho[1]);
  *residual_scale = sqrt_rho1 / (1 - alpha);
  *jacobian_scale = sqrt_rho1 * (1.0 - alpha / s * s);
}

template <typename Residuals, typename T, typename = void>
struct HasPrepare : std::false_type {};
template <typename Residuals, typename T>
struct HasPrepare<Residuals, T,
                  std::void_t<decltype(std::declval<const Residuals&>().Prepare(
                      std::declval<const T*>()))>> : std::true_type {};

// Residuals::Prepare(x) when there is one.
template <typename Residuals, typename T>
bool Prepare(const Residuals& residuals, const T* x) {
  if constexpr (HasPrepare<Residuals, T>::value) {
    return residuals.Prepare(x);
  } else {
    return true;
  }
}

template <int N, typename Residuals>
bool EvaluateCost(const Residuals& residuals, const RobustLoss& loss, const double* x,
                  double* cost) {
  double sum = 0;
  if (!Prepare(residuals, x)) return false;
  for (int i = 0; i < residuals.size(); ++i) {
    double r = 0, term = 0, unused_r = 0, unused_j = 0;
    if (!residuals(i, x, &r) || !std::isfinite(r)) return false;
    Correct(loss, r, &term, &unused_r, &unused_j);
    sum += term;
  }
  *cost = sum;
  return std::isfinite(sum);
}

// The triangular system [R | z] with R'R = J'J and R'z = J'f, from [J'J | J'f] (`normal`, upper
// triangle) by Cholesky: what rotating every row of [J | f] in (AddRow) gives, up to the rows'
// signs, at a fraction of the cost for many rows. A pivot lost to rounding (a column that J does
// not determine) leaves its row zero, as rotations would.
template <int N>
void NormalToTriangular(const double (*normal)[N + 1], double (*r)[N + 1]) {
  for (int k = 0; k < N; ++k) {
    double pivot = normal[k][k];
    for (int m = 0; m < k; ++m) pivot -= r[m][k] * r[m][k];
    if (!(pivot > 1e-13 * normal[k][k]) || !(pivot > 0)) {
      for (int j = 0; j <= N; ++j) r[k][j] = 0;
      continue;
    }
    const double diagonal = std::sqrt(pivot);
    for (int j = 0; j < k; ++j) r[k][j] = 0;
    r[k][k] = diagonal;
    for (int j = k + 1; j <= N; ++j) {
      double v = normal[k][j];
      for (int m = 0; m < k; ++m) v -= r[m][k] * r[m][j];
      r[k][j] = v / diagonal;
    }
  }
}

// The Linearization at x with every residual's derivatives taken by a Jet.
template <int N, typename Residuals>
void LinearizeWithJets(const Residuals& residuals, const RobustLoss& loss, const double* x,
                       Linearization<N>* lin) {
  using Jet = ceres::Jet<double, N>;
  *lin = Linearization<N>();
  Jet xj[N];
  for (int k = 0; k < N; ++k) {
    lin->x[k] = x[k];
    xj[k] = Jet(x[k], k);
  }
  if (!Prepare(residuals, static_cast<const Jet*>(xj))) return;
  double normal[N][N + 1] = {};  // [J'J | J'f], upper triangle.
  for (int i = 0; i < residuals.size(); ++i) {
    Jet r;
    if (!residuals(i, xj, &r) || !std::isfinite(r.a)) return;
    double term = 0, residual_scale = 1, jacobian_scale = 1;
    Correct(loss, r.a, &term, &residual_scale, &jacobian_scale);
    lin->cost += term;
    double row[N + 1];
    row[N] = r.a * residual_scale;
    for (int k = 0; k < N; ++k) {
      if (!std::isfinite(r.v[k])) return;
      row[k] = r.v[k] * jacobian_scale;
      lin->gradient[k] += row[k] * row[N];
      lin->column_sq[k] += row[k] * row[k];
    }
    for (int k = 0; k < N; ++k) {
      for (int j = k; j <= N; ++j) normal[k][j] += row[k] * row[j];
    }
  }
  NormalToTriangular<N>(normal, lin->r);
  lin->ok = std::isfinite(lin->cost);
}

template <int N, typename Residuals, typename = void>
struct HasLinearize : std::false_type {};
template <int N, typename Residuals>
struct HasLinearize<N, Residuals,
                    std::void_t<decltype(std::declval<const Residuals&>().Linearize(
                        std::declval<const RobustLoss&>(), std::declval<const double*>(),
                        std::declval<Linearization<N>*>()))>> : std::true_type {};

// The Linearization at x: Residuals::Linearize(loss, x, lin) when there is one (a faster way to
// the same normal equations, with lin->ok its result), else LinearizeWithJets.
template <int N, typename Residuals>
void Linearize(const Residuals& residuals, const RobustLoss& loss, const double* x,
               Linearization<N>* lin) {
  if constexpr (HasLinearize<N, Residuals>::value) {
    *lin = Linearization<N>();
    std::copy(x, x + N, lin->x);
    lin->ok = residuals.Linearize(loss, x, lin);
  } else {
    LinearizeWithJets<N>(residuals, loss, x, lin);
  }
}

// Solves min |R y - z|^2 + |diag(d) y|^2 (R, z: the scaled factor and its right-hand side).
template <int N>
bool SolveDamped(const double (*r)[N + 1], const double* d, double* y) {
  double t[N][N + 1];
  std::copy(&r[0][0], &r[0][0] + N * (N + 1), &t[0][0]);
  for (int i = 0; i < N; ++i) {
    double row[N + 1] = {};
    row[i] = d[i];
    AddRow<N>(t, row);
  }
  for (int k = N - 1; k >= 0; --k) {
    double v = t[k][N];
    for (int j = k + 1; j < N; ++j) v -= t[k][j] * y[j];
    y[k] = v / t[k][k];
    if (!std::isfinite(y[k])) return false;
  }
  return true;
}

template <int N>
void Project(const double* x, const double* delta, double step, const double* lower,
             const double* upper, double* out) {
  for (int k = 0; k < N; ++k) {
    out[k] = std::min(std::max(x[k] + step * delta[k], lower[k]), upper[k]);
  }
}

template <int N>
double Norm(const double* a, const double* b) {
  double s = 0;
  for (int k = 0; k < N; ++k) s += (a[k] - b[k]) * (a[k] - b[k]);
  return std::sqrt(s);
}

// The LM step of one iteration: J S y = -f damped by D (S the column scaling, D^2 the diagonal
// over the radius), solved in the scaled space; `delta` = S y, the unscaled step, and the cost
// change the linear model predicts for it. False when the step is invalid (the damped system
// is singular, or the model predicts no decrease).
template <int N>
bool DampedStep(const Linearization<N>& current, const double* scale, const double* diagonal,
                double radius, double* delta, double* model_cost_change) {
  double scaled_r[N][N + 1];
  for (int i = 0; i < N; ++i) {
    for (int j = 0; j < N; ++j) scaled_r[i][j] = current.r[i][j] * scale[j];
    scaled_r[i][N] = current.r[i][N];
  }
  double d[N], step[N];
  for (int k = 0; k < N; ++k) d[k] = std::sqrt(diagonal[k] / radius);
  if (!SolveDamped<N>(scaled_r, d, step)) return false;
  double g_step = 0, r_step_sq = 0;
  for (int k = 0; k < N; ++k) {
    step[k] = -step[k];
    g_step += step[k] * current.gradient[k] * scale[k];
  }
  for (int i = 0; i < N; ++i) {
    double v = 0;
    for (int j = i; j < N; ++j) v += scaled_r[i][j] * step[j];
    r_step_sq += v * v;
  }
  *model_cost_change = -(g_step + 0.5 * r_step_sq);
  for (int k = 0; k < N; ++k) delta[k] = step[k] * scale[k];
  return *model_cost_change > 0.0;
}

// The projected Armijo line search along `delta` from x (bounded problems): `delta` is scaled by
// the step that gives sufficient decrease, left as it is when none is found. `trial` is the last
// point evaluated (with derivatives); each evaluation counts in *jacobian_evaluations.
template <int N, typename Residuals>
void ProjectedLineSearch(const Residuals& residuals, const RobustLoss& loss,
                         const Linearization<N>& current, const double* x, const double* lower,
                         const double* upper, double* delta, Linearization<N>* trial,
                         int* jacobian_evaluations) {
  LineSample initial, previous, sample;
  initial.value = current.cost;
  initial.value_ok = initial.gradient_ok = true;
  double direction_max = 0;
  for (int k = 0; k < N; ++k) {
    initial.gradient += current.gradient[k] * delta[k];
    direction_max = std::max(direction_max, std::abs(delta[k]));
  }
  const auto evaluate = [&](double alpha) {
    double point[N];
    Project<N>(x, delta, alpha, lower, upper, point);
    Linearize<N>(residuals, loss, point, trial);
    ++*jacobian_evaluations;
    LineSample s;
    s.x = alpha;
    s.value = trial->cost;
    s.value_ok = trial->ok;
    if (trial->ok) {
      for (int k = 0; k < N; ++k) s.gradient += delta[k] * trial->gradient[k];
      s.gradient_ok = std::isfinite(s.gradient);
    }
    return s;
  };
  const auto sufficient_decrease = [&](const LineSample& s) {
    return s.value_ok && !(s.value > initial.value + kSufficientDecrease * initial.gradient * s.x);
  };
  sample = evaluate(1.0);
  for (int tries = 0; !sufficient_decrease(sample);) {
    if (++tries >= kMaxLineIterations) return;
    const double alpha = InterpolatedStep(initial, previous, sample, kMaxContraction * sample.x,
                                          kMinContraction * sample.x);
    if (alpha * direction_max < kMinLineStep) return;
    previous = sample;
    sample = evaluate(alpha);
  }
  for (int k = 0; k < N; ++k) delta[k] *= sample.x;
}

// The radius after an accepted step, from its relative decrease (Ceres's LM strategy).
inline double GrownRadius(double radius, double relative_decrease) {
  return std::min(kMaxRadius,
                  radius / std::max(1.0 / 3.0, 1.0 - std::pow(2.0 * relative_decrease - 1.0, 3)));
}

}  // namespace bounded_lm

// Minimises 1/2 sum rho(r_i(x)^2) over lower <= x <= upper from x (projected onto the box first);
// x is left at the last accepted point.
template <int N, typename Residuals>
BoundedLmSummary SolveBoundedLm(const Residuals& residuals, const BoundedLmOptions& options,
                                const double* lower, const double* upper, double* x) {
  using namespace bounded_lm;  // NOLINT: the helpers above
  using Termination = BoundedLmSummary::Termination;
  BoundedLmSummary summary;
  constexpr double kHuge = std::numeric_limits<double>::max();
  const RobustLoss& loss = options.loss;
  Linearization<N> current, trial;

  double zero[N] = {};
  double start[N];
  Project<N>(x, zero, 1.0, lower, upper, start);
  Linearize<N>(residuals, loss, start, &current);
  ++summary.jacobian_evaluations;
  if (!current.ok) {
    summary.message = "Residual and Jacobian evaluation failed.";
    return summary;
  }
  std::copy(start, start + N, x);
  summary.initial_cost = summary.final_cost = current.cost;
  double scale[N];
  for (int k = 0; k < N; ++k) scale[k] = 1.0 / (1.0 + std::sqrt(current.column_sq[k]));
  double x_norm = std::sqrt([&] {
    double s = 0;
    for (int k = 0; k < N; ++k) s += x[k] * x[k];
    return s;
  }());

  double radius = kInitialRadius, decrease_factor = 2.0;
  double diagonal[N];
  bool reuse_diagonal = false;
  int invalid_steps = 0;
  int iteration = 0;
  bool step_successful = true;
  auto gradient_max_norm = [&] {
    double g[N], m = 0;
    Project<N>(x, current.gradient, -1.0, lower, upper, g);
    for (int k = 0; k < N; ++k) m = std::max(m, std::abs(x[k] - g[k]));
    return m;
  };
  while (true) {
    // The end of an iteration (Ceres pushes its summary here): the limits, then the gradient
    // after a successful step, then the radius.
    summary.iterations = iteration + 1;
    if (iteration >= options.max_iterations) {
      summary.termination = Termination::kNoConvergence;
      summary.message = "Maximum number of iterations reached.";
      return summary;
    }
    if (step_successful && gradient_max_norm() <= options.gradient_tolerance) {
      summary.termination = Termination::kConvergence;
      summary.message = "Gradient tolerance reached.";
      return summary;
    }
    if (radius <= kMinRadius) {
      summary.termination = Termination::kConvergence;
      summary.message = "Minimum trust region radius reached.";
      return summary;
    }
    ++iteration;
    step_successful = false;

    if (!reuse_diagonal) {
      for (int k = 0; k < N; ++k) {
        diagonal[k] = std::min(std::max(current.column_sq[k] * scale[k] * scale[k], kMinDiagonal),
                               kMaxDiagonal);
      }
    }
    reuse_diagonal = true;
    double delta[N];
    double model_cost_change = 0;
    if (!DampedStep<N>(current, scale, diagonal, radius, delta, &model_cost_change)) {
      if (++invalid_steps >= kMaxInvalidSteps) {
        summary.message = "Too many consecutive invalid steps.";
        return summary;
      }
      radius /= decrease_factor;
      decrease_factor *= 2.0;
      continue;
    }
    invalid_steps = 0;
    ProjectedLineSearch<N>(residuals, loss, current, x, lower, upper, delta, &trial,
                           &summary.jacobian_evaluations);

    // The candidate point and its cost (the line search's last point when it is the same).
    double candidate[N];
    Project<N>(x, delta, 1.0, lower, upper, candidate);
    ++summary.residual_evaluations;
    double candidate_cost = kHuge;
    const bool same_point = std::equal(candidate, candidate + N, trial.x);
    if (same_point && trial.ok) {
      candidate_cost = trial.cost;
    } else if (!EvaluateCost<N>(residuals, loss, candidate, &candidate_cost)) {
      candidate_cost = kHuge;
    }
    if (Norm<N>(x, candidate) <=
        options.parameter_tolerance * (x_norm + options.parameter_tolerance)) {
      summary.termination = Termination::kConvergence;
      summary.message = "Parameter tolerance reached.";
      return summary;
    }
    if (std::abs(current.cost - candidate_cost) <= options.function_tolerance * current.cost) {
      summary.termination = Termination::kConvergence;
      summary.message = "Function tolerance reached.";
      return summary;
    }
    const double relative_decrease = candidate_cost >= kHuge
                                         ? std::numeric_limits<double>::lowest()
                                         : (current.cost - candidate_cost) / model_cost_change;
    if (relative_decrease > kMinRelativeDecrease) {
      if (!same_point || !trial.ok) Linearize<N>(residuals, loss, candidate, &trial);
      ++summary.jacobian_evaluations;
      if (!trial.ok) {
        summary.message = "Residual and Jacobian evaluation failed.";
        return summary;
      }
      current = trial;
      std::copy(candidate, candidate + N, x);
      x_norm = Norm<N>(x, zero);
      summary.final_cost = std::min(summary.final_cost, current.cost);
      step_successful = true;
      radius = GrownRadius(radius, relative_decrease);
      decrease_factor = 2.0;
      reuse_diagonal = false;
    } else {
      summary.final_cost = std::min(summary.final_cost, candidate_cost);
      radius /= decrease_factor;
      decrease_factor *= 2.0;
    }
  }
}

}  // namespace corridor
