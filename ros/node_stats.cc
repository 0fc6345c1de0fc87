#include "ros/node_stats.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace corridor {
namespace {

diagnostic_msgs::KeyValue Pair(const std::string& key, const std::string& value) {
  diagnostic_msgs::KeyValue pair;
  pair.key = key;
  pair.value = value;
  return pair;
}

std::string Number(double value) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.6g", value);
  return text;
}

// The q-quantile (nearest rank) of the values; NaN when there are none.
double Quantile(std::vector<double> values, double q) {
  if (values.empty()) return std::nan("");
  const size_t rank = static_cast<size_t>(std::ceil(q * static_cast<double>(values.size())));
  const size_t at = std::min(values.size() - 1, rank == 0 ? 0 : rank - 1);
  std::nth_element(values.begin(), values.begin() + static_cast<long>(at), values.end());
  return values[at];
}

}  // namespace

void NodeStats::Received(bool dropped_one) {
  std::lock_guard<std::mutex> lock(mutex_);
  ++received_;
  if (dropped_one) ++dropped_;
}

void NodeStats::Published(double latency_s) {
  std::lock_guard<std::mutex> lock(mutex_);
  ++published_;
  latencies_.push_back(latency_s);
  if (latencies_.size() > kWindow) latencies_.pop_front();
}

void NodeStats::Problem(const std::string& stamp, const std::string& status_class,
                        const std::string& why) {
  std::lock_guard<std::mutex> lock(mutex_);
  (status_class == "refused" ? refused_ : failed_) += 1;
  last_problem_ = status_class + ": " + why;
  last_problem_stamp_ = stamp;
}

diagnostic_msgs::DiagnosticStatus NodeStats::Report(const std::string& name,
                                                    const std::string& hardware_id,
                                                    double elapsed_s) {
  std::lock_guard<std::mutex> lock(mutex_);
  diagnostic_msgs::DiagnosticStatus status;
  status.name = name;
  status.hardware_id = hardware_id;
  const int64_t problems = refused_ + failed_;
  const int64_t new_problems = problems - problems_at_report_;
  const int64_t new_dropped = dropped_ - dropped_at_report_;
  const int64_t new_published = published_ - published_at_report_;
  if (new_problems > 0) {
    status.level = diagnostic_msgs::DiagnosticStatus::WARN;
    status.message = std::to_string(new_problems) + " frame(s) without depth; last at " +
                     last_problem_stamp_ + ": " + last_problem_;
  } else if (new_dropped > 0) {
    status.level = diagnostic_msgs::DiagnosticStatus::WARN;
    status.message = std::to_string(new_dropped) + " frame(s) dropped (the node is behind)";
  } else {
    status.level = diagnostic_msgs::DiagnosticStatus::OK;
    status.message = "ok";
  }
  const std::vector<double> latencies(latencies_.begin(), latencies_.end());
  status.values = {
      Pair("frames_received", std::to_string(received_)),
      Pair("frames_published", std::to_string(published_)),
      Pair("frames_dropped", std::to_string(dropped_)),
      Pair("frames_refused", std::to_string(refused_)),
      Pair("frames_failed", std::to_string(failed_)),
      Pair("latency_median_s", Number(Quantile(latencies, 0.5))),
      Pair("latency_p99_s", Number(Quantile(latencies, 0.99))),
      Pair("published_hz", Number(elapsed_s > 0 ? static_cast<double>(new_published) / elapsed_s
                                                : 0.0)),
      Pair("last_problem", last_problem_),
      Pair("last_problem_stamp", last_problem_stamp_),
  };
  problems_at_report_ = problems;
  dropped_at_report_ = dropped_;
  published_at_report_ = published_;
  return status;
}

}  // namespace corridor
