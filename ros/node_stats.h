#pragma once

#include <cstdint>
#include <deque>
#include <mutex>
#include <string>

#include <diagnostic_msgs/DiagnosticStatus.h>

namespace corridor {

// What the node reports on /diagnostics: frames received, published, dropped (replaced in the
// mailbox before the worker took them), refused and failed; the latency from image stamp to depth
// publication (median and 99th percentile of the last 1000 frames); and the last problem with its
// frame's stamp. Thread-safe: the callback, the worker and the diagnostics timer share it.
class NodeStats {
 public:
  void Received(bool dropped_one);
  void Published(double latency_s);
  // A frame without depth: its stamp, status class (refused / failed) and why.
  void Problem(const std::string& stamp, const std::string& status_class, const std::string& why);
  // The report; WARN when frames were refused, failed or dropped since the previous report.
  diagnostic_msgs::DiagnosticStatus Report(const std::string& name, const std::string& hardware_id,
                                           double elapsed_s);

 private:
  std::mutex mutex_;
  int64_t received_ = 0, published_ = 0, dropped_ = 0, refused_ = 0, failed_ = 0;
  int64_t published_at_report_ = 0, problems_at_report_ = 0, dropped_at_report_ = 0;
  std::deque<double> latencies_;  // The last kWindow latencies, s.
  std::string last_problem_, last_problem_stamp_;
  static constexpr size_t kWindow = 1000;
};

}  // namespace corridor
