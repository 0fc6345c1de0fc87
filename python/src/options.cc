#include "python/src/options.h"

#include <functional>
#include <map>
#include <string>
#include <type_traits>
#include <utility>

#include "pipeline/option_table.h"
#include "python/src/common.h"

namespace corridor {
namespace python {
namespace {

using Setter = std::function<void(RecoverDepthOptions*, const py::handle&)>;

template <typename T>
Setter Field(T RecoverDepthOptions::*field) {
  return [field](RecoverDepthOptions* o, const py::handle& v) { o->*field = py::cast<T>(v); };
}
// Sets the option the tools call `name` in *options to `value`, when its type is T
// (pipeline/option_table.h).
template <typename T>
class SetByName : public OptionVisitor {
 public:
  SetByName(std::string name, T value) : name_(std::move(name)), value_(std::move(value)) {}
  void String(const char* n, std::string* f) override { Set(n, f); }
  void Double(const char* n, double* f) override { Set(n, f); }
  void Int(const char* n, int* f) override { Set(n, f); }
  void Bool(const char* n, bool* f) override { Set(n, f); }

 private:
  template <typename F>
  void Set(const char* n, F* field) {
    if constexpr (std::is_same_v<F, T>) {
      if (name_ == n) *field = value_;
    }
  }
  const std::string name_;
  const T value_;
};

// A setter per option name of the table, each of its option's type.
class SetterNamer : public OptionVisitor {
 public:
  explicit SetterNamer(std::map<std::string, Setter>* out) : out_(out) {}
  void String(const char* name, std::string*) override { Add<std::string>(name); }
  void Double(const char* name, double*) override { Add<double>(name); }
  void Int(const char* name, int*) override { Add<int>(name); }
  void Bool(const char* name, bool*) override { Add<bool>(name); }

 private:
  template <typename T>
  void Add(const std::string& name) {
    (*out_)[name] = [name](RecoverDepthOptions* o, const py::handle& v) {
      SetByName<T> setting(name, py::cast<T>(v));
      VisitRecoverDepthOptions(o, &setting);
    };
  }
  std::map<std::string, Setter>* out_;
};

template <typename S, typename T>
Setter Nested(S RecoverDepthOptions::*group, T S::*field) {
  return [group, field](RecoverDepthOptions* o, const py::handle& v) {
    (o->*group).*field = py::cast<T>(v);
  };
}

// The RecoverDepthOptions fields by name: every name the tools' flags use (pipeline/option_table.h,
// the one list the ROS node's parameters share), plus the option structs' own field names.
const std::map<std::string, Setter>& Setters() {
  static const std::map<std::string, Setter> setters = [] {
    using O = RecoverDepthOptions;
    std::map<std::string, Setter> s;
    // The flag names: each setter finds its field by visiting the options it is given.
    RecoverDepthOptions defaults;
    SetterNamer namer(&s);
    VisitRecoverDepthOptions(&defaults, &namer);
    // RecoverDepthOptions' own field names where they differ from the flags'.
    s["min_width"] = Field(&O::min_width);
    s["max_width"] = Field(&O::max_width);
    s["max_abs_yaw"] = Field(&O::max_abs_yaw);
    s["max_abs_pitch"] = Field(&O::max_abs_pitch);
    s["max_line_error"] = Field(&O::max_line_error);
    s["estimate_ceiling"] = Field(&O::estimate_ceiling);
    s["ceiling_checks_baseboards"] = Field(&O::ceiling_checks_baseboards);
    s["ceiling_checks_inner_lines"] = Field(&O::ceiling_checks_inner_lines);
    s["estimate_end_wall"] = Field(&O::estimate_end_wall);
    // The solvers' shared options.
    s["loss"] = Nested(&O::solver_options, &SolverOptions::loss);
    s["loss_scale"] = Nested(&O::solver_options, &SolverOptions::loss_scale);
    s["max_rounds"] = Nested(&O::solver_options, &SolverOptions::max_rounds);
    s["initial_pitch"] = Nested(&O::solver_options, &SolverOptions::initial_pitch);
    return s;
  }();
  return setters;
}

}  // namespace

RecoverDepthOptions OptionsFromKwargs(const py::kwargs& kwargs, py::object* camera_height) {
  RecoverDepthOptions options;
  *camera_height = py::none();
  for (const auto& item : kwargs) {
    const std::string name = py::cast<std::string>(item.first);
    if (name == "camera_height") {
      *camera_height = py::reinterpret_borrow<py::object>(item.second);
      continue;
    }
    const auto it = Setters().find(name);
    if (it == Setters().end()) {
      throw py::type_error("unexpected keyword argument '" + name + "'");
    }
    try {
      it->second(&options, item.second);
    } catch (const py::cast_error&) {
      throw py::type_error("keyword argument '" + name + "': wrong type " +
                           std::string(py::str(py::type::of(item.second))));
    }
  }
  return options;
}

std::vector<std::string> OptionNames() {
  std::vector<std::string> names;
  for (const auto& entry : Setters()) names.push_back(entry.first);
  return names;
}

}  // namespace python
}  // namespace corridor
