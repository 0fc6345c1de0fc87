#include "pipeline/roll_leveling.h"

#include <cmath>
#include <limits>
#include <sstream>
#include <utility>

#include <opencv2/imgproc.hpp>

#include "perception/roll_estimate.h"
#include "pipeline/frame_handover.h"

namespace corridor {

bool LevelRoll(const DepthRecoverer& level, const Camera& camera,
               const CorridorGeometry* previous, RecoverDepthResult* result) {
  if (result->handover == nullptr || result->handover->image.empty()) return false;
  const cv::Mat& bgr = result->handover->image;
  const RollEstimate roll = EstimateRoll(bgr, camera, result->geometry, RollEstimateOptions());
  if (!roll.found) return false;
  std::ostringstream note;
  note.precision(2);
  note << std::fixed << "a roll of " << roll.roll * 180.0 / M_PI << " deg (" << roll.segments
       << " vertical edges)";
  // The frame turned level: its pixel p goes to RollTurn(-roll) p.
  const cv::Mat to_level = RollTurn(camera, -roll.roll);
  cv::Mat level_bgr;
  cv::warpAffine(bgr, level_bgr, to_level, bgr.size(), cv::INTER_LINEAR, cv::BORDER_REPLICATE);
  RecoverDepthResult turned;
  level.Detect(level_bgr, camera, &turned, nullptr);
  // The choice is made on the two layouts; the one taken is finished (chosen_solve.h).
  if (turned.ReadyToReconstruct()) level.ReconstructLayout(camera, &turned, previous);
  // A frame refused as seen keeps its refusal unless the level frame is recovered.
  if (!result->status.ok() && !turned.status.ok()) return false;
  if (!turned.status.ok()) {
    result->AddNote(note.str() + " found, but the level frame gave no depth (" +
                    turned.status.message() + "): recovered as seen");
    return false;
  }
  // A level frame less sure of its layout than the frame as seen: the turn has not made the
  // evidence clearer, and the frame's own answer stands.
  if (turned.confidence < result->confidence) {
    std::ostringstream why;
    why.precision(2);
    why << std::fixed << note.str() << " found, but the level frame is less sure of its layout ("
        << turned.confidence << " against " << result->confidence << "): recovered as seen";
    result->AddNote(why.str());
    return false;
  }
  level.FinishLayout(camera, &turned);
  // The depth back in the frame's pixels: depth(p) = level depth(RollTurn(-roll) p).
  cv::Mat depth;
  if (!turned.depth.empty()) {
    cv::warpAffine(turned.depth, depth, to_level, turned.depth.size(),
                   cv::INTER_NEAREST | cv::WARP_INVERSE_MAP, cv::BORDER_CONSTANT,
                   cv::Scalar(std::numeric_limits<double>::quiet_NaN()));
  }
  JunctionPair junctions = std::move(result->junctions);
  std::shared_ptr<const FrameHandover> handover = std::move(result->handover);
  const StageTimes times = result->times;
  *result = std::move(turned);
  result->junctions = std::move(junctions);
  result->handover = std::move(handover);
  result->depth = depth;
  result->roll = roll.roll;
  result->times.perception += times.perception;
  result->times.total += times.total;
  result->AddNote("recovered level: " + note.str());
  return true;
}

}  // namespace corridor
