#pragma once

// Keyword arguments to RecoverDepthOptions: the field names of RecoverDepthOptions and the tools'
// flag names (tools/tool_flags.cc), e.g. solver="lm", max_range=20.0, end_wall=False.

#include <string>
#include <vector>

#include <pybind11/pybind11.h>

#include "corridor_depth/recover_depth.h"

namespace corridor {
namespace python {

// The options with `kwargs` applied over the defaults, and camera_height (None when not given).
// TypeError naming an unknown keyword or a value of the wrong type. Values are checked where the
// options are used (DepthRecoverer::Create).
RecoverDepthOptions OptionsFromKwargs(const pybind11::kwargs& kwargs,
                                      pybind11::object* camera_height);

// Every keyword OptionsFromKwargs takes besides camera_height, sorted.
std::vector<std::string> OptionNames();

}  // namespace python
}  // namespace corridor
