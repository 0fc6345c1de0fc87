#include "perception/junction_memory.h"

#include <utility>

namespace corridor {
namespace {

// A search fills at most five lines' support (left, right, their lower lines, or the single).
constexpr int kLines = 5;

struct JunctionMemory {
  std::vector<Eigen::Vector2d> support[kLines];  // [0, supports) are spare.
  int supports = 0;
  std::vector<cv::Vec4f> segments;
};

JunctionMemory& ThreadMemory() {
  thread_local JunctionMemory memory;
  return memory;
}

}  // namespace

void RecycleJunctionMemory(JunctionPair* junctions) {
  JunctionMemory& memory = ThreadMemory();
  for (JunctionLine* line : {&junctions->left, &junctions->right, &junctions->left_lower,
                             &junctions->right_lower, &junctions->single}) {
    if (line->support.capacity() == 0) continue;
    if (memory.supports < kLines) {
      memory.support[memory.supports++] = std::move(line->support);
    }
    line->support = {};
  }
  if (junctions->segments.capacity() > memory.segments.capacity()) {
    memory.segments = std::move(junctions->segments);
  }
  junctions->segments = {};
}

std::vector<Eigen::Vector2d> SpareSupport() {
  JunctionMemory& memory = ThreadMemory();
  if (memory.supports == 0) return {};
  std::vector<Eigen::Vector2d> support = std::move(memory.support[--memory.supports]);
  support.clear();
  return support;
}

std::vector<cv::Vec4f> SpareSegments() {
  std::vector<cv::Vec4f> segments = std::move(ThreadMemory().segments);
  segments.clear();
  return segments;
}

}  // namespace corridor
