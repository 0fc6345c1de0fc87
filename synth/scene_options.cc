#include "synth/scene_options.h"

#include <cmath>
#include <sstream>

namespace corridor {
namespace synth {
namespace {

bool InRange(const char* name, double value, double lo, double hi, std::string* why) {
  if (std::isfinite(value) && value >= lo && value <= hi) return true;
  if (why != nullptr) {
    std::ostringstream msg;
    msg << name << " = " << value << " is outside [" << lo << ", " << hi << "]";
    *why = msg.str();
  }
  return false;
}

}  // namespace

bool SceneOptions::Check(std::string* why) const {
  return InRange("width", width, 0.8, 20, why) &&
         InRange("ceiling_height", ceiling_height, 1.8, 10, why) &&
         InRange("length", length, 5, 500, why) && InRange("clutter", clutter, 0, 1, why) &&
         InRange("door_density", door_density, 0, 1, why) &&
         InRange("floor_wall_contrast", floor_wall_contrast, 0, 1, why) &&
         InRange("baseboard_height", baseboard_height, 0, 0.3, why) &&
         InRange("baseboard_contrast", baseboard_contrast, 0, 1, why) &&
         InRange("tile_size", tile_size, 0.1, 2, why) && InRange("falloff", falloff, 0, 1, why) &&
         InRange("blur_sigma", blur_sigma, 0, 5, why) &&
         InRange("noise_sigma", noise_sigma, 0, 50, why) &&
         InRange("furniture", furniture, 0, 1, why) &&
         InRange("floor_gloss", floor_gloss, 0, 0.8, why) &&
         InRange("floor_gloss_reach", floor_gloss_reach, 0, 5, why);
}

}  // namespace synth
}  // namespace corridor
