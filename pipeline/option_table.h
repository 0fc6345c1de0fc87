#pragma once

#include <string>

#include "corridor_depth/recover_depth.h"

namespace corridor {

// The RecoverDepthOptions that corridor_depth's flags set (tools/tool_flags.cc), by the flag's
// name, so that the ROS node's private parameters and the Python module's keywords carry the same
// names: solver, max_range, min_confidence, ... A visitor sees each option's name and field; the
// field holds its default on the way in. No gflags and no ROS here; ros/tests/option_table_test.cc
// checks it against the tool's flags (same names, same defaults, same fields).
class OptionVisitor {
 public:
  virtual ~OptionVisitor() = default;
  virtual void String(const char* name, std::string* field) = 0;
  virtual void Double(const char* name, double* field) = 0;
  virtual void Int(const char* name, int* field) = 0;
  virtual void Bool(const char* name, bool* field) = 0;
};

// Calls the visitor once per option, in a fixed order.
void VisitRecoverDepthOptions(RecoverDepthOptions* options, OptionVisitor* visitor);

}  // namespace corridor
