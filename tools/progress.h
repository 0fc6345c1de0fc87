#pragma once

#include <chrono>
#include <string>

namespace corridor {

// A one-line progress report on stderr: frames done, frames per second and time left.
// Silent when there is a single frame.
class Progress {
 public:
  Progress(std::string label, int total);
  void Tick(int done);  // Redraws at most every 0.2 s, and always at the end.
  void Finish();        // Ends the line.

 private:
  std::string label_;
  int total_;
  std::chrono::steady_clock::time_point start_, last_draw_;
  bool drawn_ = false;
};

}  // namespace corridor
