#pragma once

#include <chrono>
#include <string>

namespace corridor {

// Progress of a long run on stderr: done/total, rate and time left. On a terminal, one line redrawn
// in place (at most every 0.2 s); when stderr is a file or a pipe, plain lines without carriage
// returns, at most one every 5 s, and one at the end. Silent when there is a single item.
class Progress {
 public:
  Progress(std::string label, int total, std::string unit = "frames");
  void Tick(int done);  // Reports `done` items finished (always reported when done == total).
  void Break();         // Ends a line drawn in place, so that a message can follow on its own.
  void Finish();        // Ends the line.

 private:
  std::string label_;
  std::string unit_;
  int total_;
  bool terminal_;
  std::chrono::steady_clock::time_point start_, last_draw_;
  bool drawn_ = false;
  bool open_line_ = false;  // A line drawn in place and not yet ended.
};

}  // namespace corridor
