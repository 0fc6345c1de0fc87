#include "synth/real_buildings.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

namespace corridor {
namespace synth {
namespace {

class Draw {
 public:
  explicit Draw(uint32_t seed) : engine_(seed) {}
  double Uniform(double lo, double hi) { return lo + (hi - lo) * (engine_() / 4294967296.0); }
  bool Chance(double p) { return Uniform(0, 1) < p; }

 private:
  std::mt19937 engine_;
};

enum class Rig { kRobot,
                 kHead,
                 kLow };

constexpr double kDeg = M_PI / 180.0;

// Switches the class's parts on in `s`.
void SetParts(const std::string& name, Draw* d, SceneOptions* s) {
  const bool mix = name == "mix";
  const auto on = [&](const char* cls) { return name == cls || (mix && d->Chance(0.4)); };
  if (name == "rail") {
    const double pick = d->Uniform(0, 1);
    s->handrails = pick < 0.7;
    s->chair_rails = pick >= 0.5;
  } else if (mix) {
    s->handrails = d->Chance(0.4);
    s->chair_rails = d->Chance(0.4);
  }
  s->wainscot = on("wainscot");
  if (name == "furniture") s->furniture = d->Uniform(0.5, 1.0);
  if (mix) s->furniture = d->Uniform(0.0, 0.8);
  if (name == "floor") {
    const double pick = d->Uniform(0, 1);
    s->runner = pick < 0.75;
    s->floor_stripes = pick >= 0.5;
  } else if (mix) {
    s->runner = d->Chance(0.4);
    s->floor_stripes = d->Chance(0.4);
  }
  s->carpet = on("carpet");
  s->glass_walls = on("glass");
  s->window_bands = on("windows");
  s->pillars = on("pillars");
  if (name == "glossy") s->floor_gloss = d->Uniform(0.25, 0.6);
  if (name == "satin") {
    s->floor_gloss = d->Uniform(0.3, 0.7);
    s->floor_gloss_reach = d->Uniform(0.03, 0.3);
  }
  if (name == "baseboard") {
    s->baseboard_height = d->Uniform(0.04, 0.22);
    s->baseboard_contrast = d->Uniform(0.0, 0.9);
  }
}

Rig PickRig(const std::string& name, Draw* d) {
  if (name == "head") return Rig::kHead;
  if (name == "low") return Rig::kLow;
  if (name == "mix") {
    const double pick = d->Uniform(0, 1);
    return pick < 0.4 ? Rig::kRobot : (pick < 0.8 ? Rig::kHead : Rig::kLow);
  }
  return Rig::kRobot;
}

ScenePreset MakeScene(const std::string& name, uint32_t seed, const RealBuildingsOptions& o) {
  Draw d(seed);
  ScenePreset preset;
  char folder[64];
  std::snprintf(folder, sizeof(folder), "%s_s%u", name.c_str(), seed);
  preset.name = folder;
  SceneOptions& s = preset.scene;
  s.width = d.Uniform(1.6, 3.2);
  s.ceiling_height = d.Uniform(2.4, 3.2);
  s.length = d.Uniform(35.0, 60.0);
  s.clutter = 0.0;
  s.door_density = d.Uniform(0.2, 0.6);
  s.floor_wall_contrast = d.Uniform(0.5, 1.0);
  s.baseboard_contrast = d.Uniform(0.2, 0.8);
  s.seed = seed;
  SetParts(name, &d, &s);
  const Rig rig = PickRig(name, &d);
  double height = 0, pitch_lo = 0, pitch_hi = 0, roll = 0;
  switch (rig) {
    case Rig::kHead:
      height = d.Uniform(1.4, 1.8), pitch_lo = 5 * kDeg, pitch_hi = 30 * kDeg, roll = 3 * kDeg;
      break;
    case Rig::kLow:
      height = d.Uniform(0.2, 0.5), pitch_lo = 0.0, pitch_hi = 0.08;
      break;
    case Rig::kRobot:
      height = d.Uniform(0.55, 0.75), pitch_lo = 0.0, pitch_hi = 0.10;
      break;
  }
  preset.camera = Camera::FromHorizontalFov(o.width_px, o.height_px, o.hfov_deg * kDeg, height);
  const double half = 0.5 * s.width;
  for (int i = 0; i < o.frames; ++i) {
    CameraPose pose;
    pose.height = height;
    pose.pitch = d.Uniform(pitch_lo, pitch_hi);
    pose.yaw = d.Uniform(-0.12, 0.12);
    pose.offset = d.Uniform(-0.3, 0.3) * half;
    pose.roll = roll > 0 ? d.Uniform(-roll, roll) : 0.0;
    pose.distance = 1.5 + 0.8 * i;
    preset.poses.push_back(pose);
  }
  return preset;
}

}  // namespace

const std::vector<std::string>& RealBuildingClasses() {
  static const std::vector<std::string> kClasses = {"rail", "wainscot", "furniture", "floor",
                                                    "carpet", "glass", "windows", "pillars",
                                                    "head", "low", "mix", "glossy", "satin",
                                                    "baseboard"};
  return kClasses;
}

uint32_t RealBuildingSeed(const std::string& name) {
  const auto& classes = RealBuildingClasses();
  const auto it = std::find(classes.begin(), classes.end(), name);
  return 2900u + 100u * static_cast<uint32_t>(it - classes.begin());
}

Status RealBuildingsPreset(const std::string& name, const RealBuildingsOptions& options,
                           std::vector<ScenePreset>* presets) {
  const auto& classes = RealBuildingClasses();
  if (name != "all" && std::find(classes.begin(), classes.end(), name) == classes.end()) {
    std::string valid = "all";
    for (const auto& c : classes) valid += ", " + c;
    return Status::InvalidArgument("unknown real-buildings class '" + name + "'; valid: " + valid);
  }
  if (options.scenes < 1 || options.scenes > 14 || options.frames < 1 || options.frames > 40) {
    return Status::InvalidArgument("real-buildings scenes must be in [1, 14], frames in [1, 40]");
  }
  const Camera check = Camera::FromHorizontalFov(options.width_px, options.height_px,
                                                 options.hfov_deg * kDeg, 1.0);
  std::string why;
  if (!check.Check(&why)) return Status::InvalidArgument("camera: " + why);
  presets->clear();
  for (const auto& c : classes) {
    if (name != "all" && name != c) continue;
    for (int i = 0; i < options.scenes; ++i) {
      presets->push_back(MakeScene(c, RealBuildingSeed(c) + 7u * static_cast<uint32_t>(i), options));
    }
  }
  return Status::Ok();
}

}  // namespace synth
}  // namespace corridor
