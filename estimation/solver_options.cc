#include "corridor_depth/solver_options.h"

#include <cmath>
#include <sstream>

namespace corridor {
namespace {

bool Fail(std::string* why, const std::string& message) {
  if (why != nullptr) *why = message;
  return false;
}

bool CheckRange(const char* name, double lo, double hi, double step, std::string* why) {
  std::ostringstream msg;
  if (!std::isfinite(lo) || !std::isfinite(hi) || !std::isfinite(step)) {
    msg << name << " range and step must be finite";
  } else if (!(lo < hi)) {
    msg << name << " range [" << lo << ", " << hi << "] is empty or inverted";
  } else if (!(step > 0)) {
    msg << name << " step " << step << " must be positive";
  } else if ((hi - lo) / step > 1e6) {
    msg << name << " step " << step << " gives more than a million grid values";
  } else {
    return true;
  }
  return Fail(why, msg.str());
}

}  // namespace

const char* SolverTypeToString(SolverType type) {
  switch (type) {
    case SolverType::kGridSearch:
      return "grid";
    case SolverType::kClosedForm:
      return "closed_form";
    case SolverType::kLevenbergMarquardt:
      return "lm";
    case SolverType::kJoint:
      return "joint";
  }
  return "unknown";
}

bool StringToSolverType(const std::string& name, SolverType* type) {
  for (SolverType t : {SolverType::kGridSearch, SolverType::kClosedForm,
                       SolverType::kLevenbergMarquardt, SolverType::kJoint}) {
    if (name == SolverTypeToString(t)) {
      *type = t;
      return true;
    }
  }
  return false;
}

std::string ValidSolverNames() {
  return "grid, closed_form, lm, joint, or a chain joined by '+' such as closed_form+lm";
}

bool ParseSolverChain(const std::string& name, std::vector<SolverType>* chain, std::string* why) {
  chain->clear();
  std::stringstream stream(name);
  std::string part;
  while (std::getline(stream, part, '+')) {
    SolverType type;
    if (!StringToSolverType(part, &type)) {
      return Fail(why, "unknown solver '" + part + "' in '" + name + "'; valid: " +
                           ValidSolverNames());
    }
    chain->push_back(type);
  }
  if (chain->empty() || name.back() == '+') {
    return Fail(why, "empty solver name '" + name + "'; valid: " + ValidSolverNames());
  }
  return true;
}

bool GridSearchOptions::Check(std::string* why) const {
  if (!CheckRange("yaw", yaw_min, yaw_max, yaw_step, why) ||
      !CheckRange("pitch", pitch_min, pitch_max, pitch_step, why) ||
      !CheckRange("offset", offset_min, offset_max, offset_step, why) ||
      !CheckRange("width", width_min, width_max, width_step, why)) {
    return false;
  }
  if (width_min <= 0) return Fail(why, "width range must be positive");
  if (refinement_levels < 0 || refinement_levels > 8) {
    return Fail(why, "refinement_levels must be in [0, 8]");
  }
  if (!(refinement_factor >= 2 && refinement_factor <= 100)) {
    return Fail(why, "refinement_factor must be in [2, 100]");
  }
  return true;
}

bool LmOptions::Check(std::string* why) const {
  if (!(max_abs_yaw > 0 && max_abs_yaw < M_PI / 2)) {
    return Fail(why, "max_abs_yaw must be in (0, pi/2)");
  }
  if (!(max_abs_pitch > 0 && max_abs_pitch < M_PI / 2)) {
    return Fail(why, "max_abs_pitch must be in (0, pi/2)");
  }
  if (max_iterations <= 0) return Fail(why, "max_iterations must be positive");
  if (!(function_tolerance > 0 && parameter_tolerance > 0 && gradient_tolerance > 0)) {
    return Fail(why, "LM tolerances must be positive");
  }
  if (!(initial_width > 0 && std::isfinite(initial_width))) {
    return Fail(why, "initial_width must be positive");
  }
  return true;
}

bool SolverOptions::Check(std::string* why) const {
  if (loss != "none" && loss != "huber" && loss != "cauchy") {
    return Fail(why, "unknown loss '" + loss + "'; valid: none, huber, cauchy");
  }
  if (!(loss_scale > 0 && std::isfinite(loss_scale))) return Fail(why, "loss_scale must be > 0");
  if (!(trim_sigmas >= 0 && std::isfinite(trim_sigmas))) {
    return Fail(why, "trim_sigmas must be >= 0 (0 = no trimming)");
  }
  if (!(loss_sigmas >= 0 && std::isfinite(loss_sigmas))) {
    return Fail(why, "loss_sigmas must be >= 0 (0 = the fixed loss_scale)");
  }
  if (!(max_weight_ratio >= 0 && std::isfinite(max_weight_ratio))) {
    return Fail(why, "max_weight_ratio must be >= 0 (0 = the weights as given)");
  }
  if (max_rounds <= 0 || max_rounds > 100) return Fail(why, "max_rounds must be in [1, 100]");
  if (!(round_tolerance > 0)) return Fail(why, "round_tolerance must be positive");
  if (!std::isfinite(initial_pitch) || std::abs(initial_pitch) >= M_PI / 2) {
    return Fail(why, "initial_pitch must be finite and within (-pi/2, pi/2)");
  }
  return grid.Check(why) && lm.Check(why);
}

}  // namespace corridor
