#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "corridor_depth/corridor_geometry.h"
#include "corridor_depth/recover_depth.h"

namespace corridor {

// What a sequence carries from frame to frame: the last good geometry, with the width of the
// recent frames: the median of the last kRecent widths that were measured, not held. It
// stands in when one junction is hidden and is held when the next width is much narrower
// (RecoverDepthOptions::max_width_change). The median, because one frame's wrong wide width (a
// line beyond the wall taken for a junction) would otherwise be held over the right frames after
// it. Held kMaxHeld frames in a row (or its walls scaled to its trusted ceiling,
// max_ceiling_change), the width is let go for one frame and the recent widths start again from
// it: the corridor may really have narrowed, or the held width (the trusted ceiling) was the
// wrong one. A much narrower width a frame kept against the hold (its own evidence strong,
// RecoverDepthResult::width_kept) counts as held here: that frame keeps it, the sequence does not
// learn it (one box's foot would otherwise pull the recent width down for five frames).
// Its ceiling height is the last one whose two sides agreed (RecoverDepthResult::ceiling_trusted),
// or none: only such a height is held over a frame whose sides disagree. But when at least
// kMinRecentCeilings of the last kRecent frames' own heights (measured, not held) have a median above the
// camera more than kCeilingOutvoted (|log ratio|) from it, that median is carried instead: one
// frame whose two sides agreed on a wrong line (window bands' tops on both walls) is outvoted by
// the frames around it. A frame not in doubt that kept its own ceiling (its two sides too weak to
// compare) far from the trusted one contests it: no height is carried until one is trusted again.
class SequencePrior {
 public:
  static constexpr int kMaxHeld = 3;
  static constexpr int kRecent = 5;
  static constexpr int kMinRecentCeilings = 3;
  static constexpr double kCeilingOutvoted = 0.15;

  // The geometry to pass to DepthRecoverer::Reconstruct as `previous`; null for none.
  const CorridorGeometry* Previous() const {
    return has_previous_ && held_ < kMaxHeld ? &previous_ : nullptr;
  }

  // Records a frame after Reconstruct; failed frames change nothing.
  void Update(const RecoverDepthResult& result) {
    if (!result.status.ok() || !result.has_geometry) return;
    // Before the first frame previous_ is default-constructed: no ceiling (0).
    double trusted = result.ceiling_trusted || result.ceiling_held
                         ? result.geometry.ceiling_height
                         : previous_.ceiling_height;
    if (result.ceiling.found && !result.ceiling_held) PushRecent(result.ceiling.height, &ceilings_);
    const double h = result.geometry.camera_height;
    // A frame that kept its own ceiling against the trusted one (RecoverDepthResult::ceiling_kept),
    // more than kCeilingOutvoted from it, contests it: the trusted height came with other frames'
    // walls, this one with the frame's own, and the sequence no longer knows which is right, so it
    // holds none until a frame's two sides agree again.
    const double own = result.geometry.ceiling_height;
    if (result.ceiling_kept && trusted > h && own > h &&
        std::abs(std::log((own - h) / (trusted - h))) > kCeilingOutvoted) {
      trusted = 0;
    }
    if (trusted > h && static_cast<int>(ceilings_.size()) >= kMinRecentCeilings) {
      const double recent = Median(ceilings_);
      if (recent > h && std::abs(std::log((recent - h) / (trusted - h))) > kCeilingOutvoted) {
        trusted = recent;
      }
    }
    const bool let_go = has_previous_ && held_ >= kMaxHeld;
    previous_ = result.geometry;
    previous_.ceiling_height = trusted;
    has_previous_ = true;
    const bool not_measured = result.width_held || result.walls_scaled || result.width_kept;
    held_ = not_measured ? held_ + 1 : 0;
    if (let_go) widths_.clear();
    if (!not_measured) PushRecent(result.geometry.width, &widths_);
    if (!widths_.empty()) previous_.width = Median(widths_);
  }

 private:
  // Appends `value`, dropping the oldest beyond kRecent.
  static void PushRecent(double value, std::vector<double>* recent) {
    if (recent->size() == kRecent) recent->erase(recent->begin());
    recent->push_back(value);
  }

  // The median (the lower middle one of an even count) of a non-empty list.
  static double Median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values[(values.size() - 1) / 2];
  }

  CorridorGeometry previous_;
  std::vector<double> widths_;    // The last measured (not held) widths, oldest first.
  std::vector<double> ceilings_;  // The last measured (not held) ceiling heights, oldest first.
  bool has_previous_ = false;
  int held_ = 0;  // Frames in a row whose width was held or walls scaled.
};

}  // namespace corridor
