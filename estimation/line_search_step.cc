#include "estimation/line_search_step.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <Eigen/Eigenvalues>

namespace corridor {
namespace {

constexpr int kMaxCoefficients = 6;  // three samples with value and derivative: a quintic

// Coefficients, highest power first.
struct Polynomial {
  double c[kMaxCoefficients] = {};
  int size = 0;

  double operator()(double x) const {
    double v = 0;
    for (int i = 0; i < size; ++i) v = v * x + c[i];
    return v;
  }
};

// The polynomial of lowest degree through every valid value and derivative (Gaussian
// elimination with partial pivoting on the small square system). False when it is singular.
bool Interpolate(const LineSample* samples, int count, Polynomial* p) {
  double a[kMaxCoefficients][kMaxCoefficients + 1] = {};
  int rows = 0;
  for (int i = 0; i < count; ++i) rows += samples[i].value_ok + samples[i].gradient_ok;
  if (rows == 0 || rows > kMaxCoefficients) return false;
  const int degree = rows - 1;
  int row = 0;
  for (int i = 0; i < count; ++i) {
    const LineSample& s = samples[i];
    if (s.value_ok) {
      for (int j = 0; j <= degree; ++j) a[row][j] = std::pow(s.x, degree - j);
      a[row++][rows] = s.value;
    }
    if (s.gradient_ok) {
      for (int j = 0; j < degree; ++j) a[row][j] = (degree - j) * std::pow(s.x, degree - j - 1);
      a[row++][rows] = s.gradient;
    }
  }
  for (int k = 0; k < rows; ++k) {
    int pivot = k;
    for (int i = k + 1; i < rows; ++i) {
      if (std::abs(a[i][k]) > std::abs(a[pivot][k])) pivot = i;
    }
    if (a[pivot][k] == 0) return false;
    for (int j = 0; j <= rows; ++j) std::swap(a[k][j], a[pivot][j]);
    for (int i = k + 1; i < rows; ++i) {
      const double f = a[i][k] / a[k][k];
      for (int j = k; j <= rows; ++j) a[i][j] -= f * a[k][j];
    }
  }
  p->size = rows;
  for (int k = rows - 1; k >= 0; --k) {
    double v = a[k][rows];
    for (int j = k + 1; j < rows; ++j) v -= a[k][j] * p->c[j];
    p->c[k] = v / a[k][k];
  }
  return true;
}

// The real parts of the roots of p (complex roots included, as Ceres checks them too); their
// number in *count. Degrees 1 and 2 in closed form, higher ones as the eigenvalues of the
// balanced companion matrix.
bool RealPartsOfRoots(const Polynomial& p_in, double* roots, int* count) {
  *count = 0;
  int first = 0;
  while (first < p_in.size - 1 && p_in.c[first] == 0) ++first;
  const int degree = p_in.size - 1 - first;
  const double* c = p_in.c + first;
  if (degree <= 0) return true;
  if (degree == 1) {
    roots[(*count)++] = -c[1] / c[0];
    return true;
  }
  if (degree == 2) {
    const double a = c[0], b = c[1], cc = c[2], d = b * b - 4 * a * cc;
    const double sqrt_d = std::sqrt(std::abs(d));
    if (d >= 0) {
      roots[0] = b >= 0 ? (-b - sqrt_d) / (2.0 * a) : (2.0 * cc) / (-b + sqrt_d);
      roots[1] = b >= 0 ? (2.0 * cc) / (-b - sqrt_d) : (-b + sqrt_d) / (2.0 * a);
    } else {
      roots[0] = roots[1] = -b / (2.0 * a);
    }
    *count = 2;
    return true;
  }
  using Matrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxCoefficients,
                               kMaxCoefficients>;
  Matrix companion = Matrix::Zero(degree, degree);
  for (int i = 1; i < degree; ++i) companion(i, i - 1) = 1.0;
  for (int i = 0; i < degree; ++i) companion(i, degree - 1) = -c[degree - i] / c[0];
  // Balance (powers of two: exact) so that the eigenvalues are accurate.
  for (bool changed = true; changed;) {
    changed = false;
    for (int i = 0; i < degree; ++i) {
      double row_norm = 0, col_norm = 0;
      for (int j = 0; j < degree; ++j) {
        if (j == i) continue;
        row_norm += std::abs(companion(i, j));
        col_norm += std::abs(companion(j, i));
      }
      if (row_norm == 0 || col_norm == 0) continue;
      int exponent = 0;
      std::frexp(row_norm / col_norm, &exponent);
      exponent /= 2;
      if (exponent == 0) continue;
      if (std::ldexp(col_norm, exponent) + std::ldexp(row_norm, -exponent) <
          0.9 * (col_norm + row_norm)) {
        changed = true;
        for (int j = 0; j < degree; ++j) {
          if (j == i) continue;
          companion(i, j) = std::ldexp(companion(i, j), -exponent);
          companion(j, i) = std::ldexp(companion(j, i), exponent);
        }
      }
    }
  }
  Eigen::EigenSolver<Matrix> solver(companion, false);
  if (solver.info() != Eigen::Success) return false;
  for (int i = 0; i < degree; ++i) roots[(*count)++] = solver.eigenvalues()(i).real();
  return true;
}

}  // namespace

double InterpolatedStep(const LineSample& initial, const LineSample& previous,
                        const LineSample& current, double min_step, double max_step) {
  if (!current.value_ok) return std::min(std::max(current.x * 0.5, min_step), max_step);
  LineSample samples[3] = {initial, current, previous};
  const int count = previous.value_ok ? 3 : 2;
  Polynomial p;
  // The middle of the interval first, then its ends, then the critical points inside it.
  double best_x = (min_step + max_step) / 2.0;
  if (!Interpolate(samples, count, &p)) return best_x;
  double best = p(best_x);
  for (double x : {min_step, max_step}) {
    const double v = p(x);
    if (v < best) best = v, best_x = x;
  }
  if (p.size > 2) {
    Polynomial derivative;
    derivative.size = p.size - 1;
    for (int i = 0; i < derivative.size; ++i) derivative.c[i] = (derivative.size - i) * p.c[i];
    double roots[kMaxCoefficients];
    int num_roots = 0;
    if (RealPartsOfRoots(derivative, roots, &num_roots)) {
      for (int i = 0; i < num_roots; ++i) {
        if (roots[i] < min_step || roots[i] > max_step) continue;
        const double v = p(roots[i]);
        if (v < best) best = v, best_x = roots[i];
      }
    }
  }
  for (int i = 0; i < count; ++i) {
    if (samples[i].x < min_step || samples[i].x > max_step) continue;
    const double v = p(samples[i].x);
    if (v < best) best = v, best_x = samples[i].x;
  }
  return best_x;
}

}  // namespace corridor
