#pragma once

#include <algorithm>
#include <vector>

#include "corridor_depth/corridor_geometry.h"
#include "corridor_depth/recover_depth.h"

namespace corridor {

// What a sequence carries from frame to frame: the last good geometry, with the width of the
// recent frames: the median of the last kRecentWidths widths that were measured, not held. It
// stands in when one junction is hidden and is held when the next width is much narrower
// (RecoverDepthOptions::max_width_change). The median, because one frame's wrong wide width (a
// line beyond the wall taken for a junction) would otherwise be held over the right frames after
// it. Held kMaxHeld frames in a row (or its walls scaled to its trusted ceiling,
// max_ceiling_change), the width is let go for one frame and the recent widths start again from
// it: the corridor may really have narrowed, or the held width (the trusted ceiling) was the
// wrong one.
// Its ceiling height is the last one whose two sides agreed (RecoverDepthResult::ceiling_trusted),
// or none: only such a height is held over a frame whose sides disagree.
class SequencePrior {
 public:
  static constexpr int kMaxHeld = 3;
  static constexpr int kRecentWidths = 5;

  // The geometry to pass to DepthRecoverer::Reconstruct as `previous`; null for none.
  const CorridorGeometry* Previous() const {
    return has_previous_ && held_ < kMaxHeld ? &previous_ : nullptr;
  }

  // Records a frame after Reconstruct; failed frames change nothing.
  void Update(const RecoverDepthResult& result) {
    if (!result.status.ok() || !result.has_geometry) return;
    // Before the first frame previous_ is default-constructed: no ceiling (0).
    const double trusted = result.ceiling_trusted || result.ceiling_held
                               ? result.geometry.ceiling_height
                               : previous_.ceiling_height;
    const bool let_go = has_previous_ && held_ >= kMaxHeld;
    previous_ = result.geometry;
    previous_.ceiling_height = trusted;
    has_previous_ = true;
    held_ = result.width_held || result.walls_scaled ? held_ + 1 : 0;
    if (let_go) widths_.clear();
    if (!result.width_held && !result.walls_scaled) {
      if (widths_.size() == kRecentWidths) widths_.erase(widths_.begin());
      widths_.push_back(result.geometry.width);
    }
    if (!widths_.empty()) previous_.width = MedianWidth();
  }

 private:
  // The median of the recent widths (the lower middle one of an even count).
  double MedianWidth() const {
    std::vector<double> sorted = widths_;
    std::sort(sorted.begin(), sorted.end());
    return sorted[(sorted.size() - 1) / 2];
  }

  CorridorGeometry previous_;
  std::vector<double> widths_;  // The last measured (not held) widths, oldest first.
  bool has_previous_ = false;
  int held_ = 0;  // Frames in a row whose width was held or walls scaled.
};

}  // namespace corridor
