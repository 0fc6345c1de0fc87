#include "perception/junction_memory.h"

#include <utility>

namespace corridor {
namespace {

// A search fills at most five lines (left, right, their lower lines, or the single).
constexpr int kLines = 5;

// Spare vectors of one kind: [0, count) are spare.
template <typename T>
struct Spares {
  std::vector<T> vectors[kLines];
  int count = 0;

  void Give(std::vector<T>* v) {
    if (v->capacity() > 0 && count < kLines) vectors[count++] = std::move(*v);
    *v = {};
  }
  std::vector<T> Take() {
    if (count == 0) return {};
    std::vector<T> v = std::move(vectors[--count]);
    v.clear();
    return v;
  }
};

struct JunctionMemory {
  Spares<Eigen::Vector2d> support, edge_points;
  Spares<double> edge_weights;
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
    memory.support.Give(&line->support);
    memory.edge_points.Give(&line->edge_points);
    memory.edge_weights.Give(&line->edge_weights);
  }
  if (junctions->segments.capacity() > memory.segments.capacity()) {
    memory.segments = std::move(junctions->segments);
  }
  junctions->segments = {};
}

std::vector<Eigen::Vector2d> SpareSupport() { return ThreadMemory().support.Take(); }

std::vector<Eigen::Vector2d> SpareEdgePoints() { return ThreadMemory().edge_points.Take(); }

std::vector<double> SpareEdgeWeights() { return ThreadMemory().edge_weights.Take(); }

std::vector<cv::Vec4f> SpareSegments() {
  std::vector<cv::Vec4f> segments = std::move(ThreadMemory().segments);
  segments.clear();
  return segments;
}

}  // namespace corridor
