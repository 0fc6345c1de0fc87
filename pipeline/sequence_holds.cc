#include "pipeline/sequence_holds.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "pipeline/ceiling_agreement.h"

namespace corridor {

bool FrameInDoubt(double own_confidence, double min_confidence, double ceiling_disagreement,
                  double max_disagreement, bool junctions_tracked) {
  return own_confidence < min_confidence || ceiling_disagreement > max_disagreement ||
         junctions_tracked;
}

bool TrackConfirmedBy(const RecoverDepthOptions& options, const RecoverDepthResult& result) {
  const bool ceiling_searched = options.ceiling_height <= 0 && options.estimate_ceiling;
  return !ceiling_searched || (result.status.ok() && result.ceiling_trusted);
}

bool OwnSearchKept(const RecoverDepthOptions& options, const RecoverDepthResult& own) {
  const bool ceiling_searched = options.ceiling_height <= 0 && options.estimate_ceiling;
  return ceiling_searched && own.status.ok() && own.has_geometry && !own.junctions_tracked &&
         own.ceiling_trusted;
}

bool NoteRescue(double own_confidence, double min_confidence, RecoverDepthResult* result) {
  if (!result->width_held || !(own_confidence >= 0) || !(own_confidence < min_confidence) ||
      !(result->confidence >= min_confidence)) {
    return false;
  }
  std::ostringstream how;
  how.precision(2);
  how << std::fixed << "rescued by the held width: the frame's own confidence " << own_confidence
      << " is below " << min_confidence;
  result->AddNote(how.str());
  return true;
}

bool MuchNarrower(const CorridorGeometry& previous, double max_change, const CorridorGeometry& g) {
  return max_change > 0 && previous.width > 0 && g.width < (1 - max_change) * previous.width;
}

void HoldWidth(const CorridorGeometry& previous, double max_change, bool frame_doubted,
               CorridorGeometry* g, RecoverDepthResult* result) {
  if (!MuchNarrower(previous, max_change, *g)) return;
  bool keep_left = std::abs(g->LeftDistance() - previous.LeftDistance()) <=
                   std::abs(g->RightDistance() - previous.RightDistance());
  // A wall put too near scales its side's ceiling height above the camera by the same factor:
  // with a trusted ceiling carried and both sides' heights measured, the side whose height is
  // nearer the trusted one has the right wall (the camera may have moved sideways since).
  const double h = g->camera_height, trusted = previous.ceiling_height;
  const double* side = result->ceiling.side_height;
  const char* why = nullptr;
  if (trusted > h && side[0] > h && side[1] > h) {
    const double off_left = std::abs(std::log((side[0] - h) / (trusted - h)));
    const double off_right = std::abs(std::log((side[1] - h) / (trusted - h)));
    // Only a clear answer: one side off by what a wrong wall does, the other by under half that
    // and by less than a wrong wall does (off by more, its wall is wrong too: both lines inside
    // the floor, and keeping either puts the other wall far beyond the truth).
    const double worse = std::max(off_left, off_right), better = std::min(off_left, off_right);
    const double wrong_wall = std::log(1 + max_change);
    if (worse > wrong_wall && better < 0.5 * worse && better <= wrong_wall) {
      keep_left = off_left <= off_right;
      why = "its ceiling agrees with the trusted one";
    }
  }
  std::ostringstream how;
  how.precision(2);
  how << std::fixed << "width " << g->width << " m is much narrower than the recent frames' "
      << previous.width << " m";
  const double moved_line =
      (keep_left ? result->junctions.right : result->junctions.left).confidence;
  if (!frame_doubted) {
    if (why == nullptr) {
      how << ": kept (the frame's own evidence is strong and its ceiling does not say which wall "
             "is wrong)";
    } else if (moved_line >= kStrongJunction) {
      how << ": kept (the frame's own evidence is strong and its " << (keep_left ? "right" : "left")
          << " junction line, " << moved_line << ", too)";
    } else {
      how << ": kept (the frame's own evidence is strong; its ceiling puts the "
          << (keep_left ? "right" : "left")
          << " wall farther, as a box's face standing before the wall would)";
    }
    result->width_kept = true;
    result->AddNote(how.str());
    return;
  }
  if (why == nullptr) why = "moved less since the recent frames";
  const double kept = keep_left ? g->LeftDistance() : g->RightDistance();
  const double other = previous.width - kept;
  if (!(other > 0.05)) return;  // The kept wall is beyond the previous width: nothing to hold.
  how << ": the " << (keep_left ? "left" : "right")
      << " wall kept (" << why << "), the recent width held";
  g->offset = keep_left ? kept - 0.5 * previous.width : 0.5 * previous.width - kept;
  g->width = previous.width;
  result->width_held = true;
  result->AddNote(how.str());
}

bool CeilingHoldConsidered(const CorridorGeometry* previous, double max_disagreement,
                           double min_support, const CorridorGeometry& g,
                           RecoverDepthResult* result) {
  const double disagreement = CeilingDisagreement(result->ceiling, g.camera_height, min_support);
  const bool found = result->ceiling.found && g.HasCeiling();
  result->ceiling_trusted = found && disagreement >= 0 && disagreement <= max_disagreement;
  return max_disagreement > 0 && previous != nullptr && previous->HasCeiling() &&
         !result->ceiling_trusted;
}

void HoldCeiling(const CorridorGeometry* previous, double max_disagreement, double min_support,
                 bool frame_doubted, CorridorGeometry* g, RecoverDepthResult* result) {
  if (!CeilingHoldConsidered(previous, max_disagreement, min_support, *g, result)) return;
  const double disagreement = CeilingDisagreement(result->ceiling, g->camera_height, min_support);
  const bool found = result->ceiling.found && g->HasCeiling();
  const CorridorGeometry& held = *previous;
  std::ostringstream how;
  how.precision(2);
  how << std::fixed;
  if (found && disagreement >= 0) {
    how << "ceiling sides at " << result->ceiling.side_height[0] << " and "
        << result->ceiling.side_height[1] << " m disagree";
  } else {
    how << (found ? "ceiling sides too weak to compare" : "no ceiling found");
  }
  // A frame not in doubt keeps what its own evidence gives, its ceiling or none: a hold that
  // replaced it could only be right where the recent frames are, and they may be the ones wrong.
  if (!frame_doubted) {
    how << ": the previous frame's " << held.ceiling_height << " m not held (the frame's own "
        << "evidence is strong)";
    result->ceiling_kept = true;
    result->AddNote(how.str());
    return;
  }
  how << ": the previous frame's " << held.ceiling_height << " m held";
  g->ceiling_height = held.ceiling_height;
  result->ceiling_held = true;
  result->AddNote(how.str());
}

double WallScaleFactor(const CorridorGeometry& previous, double max_change,
                       const CorridorGeometry& g, const RecoverDepthResult& result) {
  if (!(max_change > 0) || !previous.HasCeiling() || !result.ceiling_trusted ||
      result.width_held || !(previous.width > 0) || !(g.width > 0)) {
    return 0;
  }
  const double above_previous = previous.ceiling_height - g.camera_height;
  const double above = g.ceiling_height - g.camera_height;
  if (!(above_previous > 0.1) || !(above > 0.1)) return 0;
  const double factor = above_previous / above;
  const double width_factor = previous.width / g.width;
  if (factor <= 1 + max_change || std::abs(std::log(width_factor / factor)) > std::log(1.15)) {
    return 0;
  }
  return factor;
}

void ScaleWallsToCeiling(const CorridorGeometry& previous, double max_change, bool frame_doubted,
                         CorridorGeometry* g, RecoverDepthResult* result) {
  const double factor = WallScaleFactor(previous, max_change, *g, *result);
  if (factor == 0) return;
  std::ostringstream how;
  how.precision(2);
  how << std::fixed;
  if (!frame_doubted) {
    how << "walls not scaled " << factor << "x to the previous frame's ceiling: the frame's own "
        << "evidence is strong";
    result->AddNote(how.str());
    return;
  }
  how << "both walls scaled " << factor << "x: both ceiling sides at " << g->ceiling_height
      << " m against the previous frame's " << previous.ceiling_height
      << " m (and the width alike): both junctions wrong alike";
  g->SetWallDistances(factor * g->LeftDistance(), factor * g->RightDistance());
  g->ceiling_height = previous.ceiling_height;
  result->walls_scaled = true;
  result->AddNote(how.str());
}

}  // namespace corridor
