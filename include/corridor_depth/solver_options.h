#pragma once

#include <string>
#include <vector>

namespace corridor {

// The solvers that fit the corridor model to the junction points.
enum class SolverType {
  kGridSearch,          // "grid": the paper's exhaustive search over both stages.
  kClosedForm,          // "closed_form": the vanishing-point solution (docs/geometry.md s4).
  kLevenbergMarquardt,  // "lm": Ceres Levenberg-Marquardt on the same two functors.
  kJoint,               // "joint": one LM problem over all four parameters (beyond the paper).
};

const char* SolverTypeToString(SolverType type);
bool StringToSolverType(const std::string& name, SolverType* type);
// "grid, closed_form, lm, joint" and how to chain them.
std::string ValidSolverNames();
// Parses "grid", "closed_form+lm", ... into the chain of solvers, each run from the previous
// one's estimate. Fails on an empty or unknown name, with the valid names in *why.
bool ParseSolverChain(const std::string& name, std::vector<SolverType>* chain, std::string* why);

// The paper's exhaustive search (III-B/C), with an optional coarse-to-fine refinement.
struct GridSearchOptions {
  double yaw_min = -0.314;          // Yaw range start, rad (paper: -0.314).
  double yaw_max = 0.314;           // Yaw range end, rad (paper: 0.314).
  double yaw_step = 0.05;           // Yaw step, rad (paper: 0.05).
  double pitch_min = -0.314;        // Pitch range start lambda_1, rad.
  double pitch_max = 0.314;         // Pitch range end lambda_2, rad.
  double pitch_step = 0.05;         // Pitch step alpha, rad (paper: 0.05).
  double offset_min = -2.0;         // Lateral offset range start, m.
  double offset_max = 2.0;          // Lateral offset range end, m.
  double offset_step = 0.05;        // Lateral offset step, m.
  double width_min = 0.5;           // Corridor width range start, m.
  double width_max = 10.0;          // Corridor width range end, m.
  double width_step = 0.05;         // Corridor width step, m.
  int refinement_levels = 2;        // Coarse-to-fine levels after the full grid (0 = paper's plain grid).
  double refinement_factor = 10.0;  // Each level divides the steps by this, around the best cell.
  bool absolute_cost = true;        // Minimise sum |r| as the paper's E_G; false: sum r^2.

  bool Check(std::string* why) const;
};

// Ceres Levenberg-Marquardt, for "lm" (the stage functors) and "joint".
struct LmOptions {
  double max_abs_yaw = 1.2;            // Bound on |yaw|, rad.
  double max_abs_pitch = 1.2;          // Bound on |pitch|, rad.
  int max_iterations = 50;             // Iteration limit per stage solve.
  double function_tolerance = 1e-10;   // Ceres relative cost-change tolerance.
  double parameter_tolerance = 1e-10;  // Ceres relative step tolerance.
  double gradient_tolerance = 1e-12;   // Ceres gradient tolerance.
  double initial_width = 2.0;          // Width used when no initial estimate is given, m.
  bool start_from_closed_form = true;  // "lm" without an initial estimate starts from the closed form's (geometry.md section 4), not from zero yaw/offset and initial_width; "joint" always does.

  bool Check(std::string* why) const;
};

// Options shared by every solver.
struct SolverOptions {
  std::string loss = "huber";  // Robust loss inside both functors: "none", "huber", "cauchy".
  double loss_scale = 2.0;     // Loss scale, pixels ("grid"; "joint" and "lm" with loss_sigmas 0).
  // "joint" and "lm": after the fit, each side's points farther from their fitted line than
  // trim_sigmas robust standard deviations (1.4826 times the median distance of that side's
  // points, at least a thousandth of a pixel) are dropped and the fit repeated from there, until
  // the kept points stop changing; 0 = no trimming. The scale comes from the points' own spread, so that a second line's points
  // mixed into a junction's are dropped where a fixed loss scale would still be pulled by them.
  double trim_sigmas = 3.0;
  // "joint" and "lm": the robust loss's scale is loss_sigmas robust standard deviations of the
  // residuals themselves (1.4826 times their median absolute value, at each solve's start: the
  // closed form's, then each fit's), instead of the fixed loss_scale; 0 = loss_scale. 1.345 is
  // Huber's constant (95% of least squares' efficiency on Gaussian noise). Edge points are placed
  // to a tenth of a pixel, so a fixed scale of pixels would treat as inliers the points of a
  // second edge a pixel away; points sampled on fitted lines have no spread, and any scale keeps
  // their exact fit.
  double loss_sigmas = 1.345;
  // "joint" and "lm": a point's weight counts at most max_weight_ratio times its side's median
  // weight (each side then scaled to a mean weight of 1); 0 = as given. The inverse-variance
  // weights of edge points hold up to about twice the median: the stronger points lie mostly on
  // a second edge beside the junction (docs/results.md).
  double max_weight_ratio = 2.0;
  int max_rounds = 20;            // Alternation rounds of stage 1 then stage 2 (grid, lm).
  double round_tolerance = 1e-6;  // Stop alternating when no parameter moves more than this.
  double initial_pitch = 0.0;     // Pitch prior theta_0 when no initial estimate is given, rad.
  GridSearchOptions grid;         // For "grid".
  LmOptions lm;                   // For "lm".

  bool Check(std::string* why) const;
};

}  // namespace corridor
