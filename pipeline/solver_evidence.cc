#include "pipeline/solver_evidence.h"

#include <utility>
#include <vector>

#include "perception/junction_edge_points.h"

namespace corridor {
namespace {

// One side's points into *points and *weights: the line's edge points undistorted, with their
// weights, when it has enough; else points sampled on it (weights emptied).
void SidePoints(const JunctionLine& line, const Camera& camera, bool edges, int points_per_line,
                std::vector<Eigen::Vector2d>* points, std::vector<double>* weights) {
  weights->clear();
  if (edges && static_cast<int>(line.edge_points.size()) >= points_per_line &&
      line.edge_weights.size() == line.edge_points.size()) {
    points->clear();
    for (const Eigen::Vector2d& p : line.edge_points) points->push_back(camera.Undistort(p));
    weights->assign(line.edge_weights.begin(), line.edge_weights.end());
    return;
  }
  SampleAlongLine(line, points_per_line, points);
  for (auto& p : *points) p = camera.Undistort(p);
}

}  // namespace

bool SolverSeesEdges(const RecoverDepthOptions& options) {
  return options.solver_evidence == "edges";
}

void MeasureSolverEvidence(const cv::Mat& bgr, const RecoverDepthOptions& options,
                           JunctionPair* junctions) {
  if (!SolverSeesEdges(options) || bgr.empty()) return;
  const JunctionEdgePointOptions edge_options;
  MeasureJunctionEdgePoints(bgr, edge_options, &junctions->left);
  MeasureJunctionEdgePoints(bgr, edge_options, &junctions->right);
  if (junctions->has_left_lower) {
    MeasureJunctionEdgePoints(bgr, edge_options, &junctions->left_lower);
  }
  if (junctions->has_right_lower) {
    MeasureJunctionEdgePoints(bgr, edge_options, &junctions->right_lower);
  }
}

CorridorObservation ObservationFromJunctions(const JunctionPair& junctions, const Camera& camera,
                                             const RecoverDepthOptions& options) {
  CorridorObservation observation;
  ObservationFromJunctions(junctions, camera, options, &observation);
  return observation;
}

void ObservationFromJunctions(const JunctionPair& junctions, const Camera& camera,
                              const RecoverDepthOptions& options,
                              CorridorObservation* observation) {
  std::vector<Eigen::Vector2d> left, right;
  std::vector<double> left_weights, right_weights;
  left.swap(observation->left);
  right.swap(observation->right);
  left_weights.swap(observation->left_weights);
  right_weights.swap(observation->right_weights);
  *observation = CorridorObservation::FromCamera(camera);
  const bool edges = SolverSeesEdges(options);
  SidePoints(junctions.left, camera, edges, options.points_per_line, &left, &left_weights);
  SidePoints(junctions.right, camera, edges, options.points_per_line, &right, &right_weights);
  observation->left.swap(left);
  observation->right.swap(right);
  observation->left_weights.swap(left_weights);
  observation->right_weights.swap(right_weights);
}

}  // namespace corridor
