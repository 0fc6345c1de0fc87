#pragma once

#include "corridor_depth/corridor_geometry.h"
#include "corridor_depth/recover_depth.h"

namespace corridor {

// What a sequence carries from frame to frame: the last good geometry, whose width stands in when
// one junction is hidden and is held when the next width is much narrower (RecoverDepthOptions::
// max_width_change). Held kMaxHeld frames in a row (or its walls scaled to its trusted ceiling,
// max_ceiling_change), the width is let go for one frame: the corridor may really have narrowed,
// or the held width (the trusted ceiling) was the wrong one.
// Its ceiling height is the last one whose two sides agreed (RecoverDepthResult::ceiling_trusted),
// or none: only such a height is held over a frame whose sides disagree.
class SequencePrior {
 public:
  static constexpr int kMaxHeld = 3;

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
    previous_ = result.geometry;
    previous_.ceiling_height = trusted;
    has_previous_ = true;
    held_ = result.width_held || result.walls_scaled ? held_ + 1 : 0;
  }

 private:
  CorridorGeometry previous_;
  bool has_previous_ = false;
  int held_ = 0;  // Frames in a row whose width was held or walls scaled.
};

}  // namespace corridor
