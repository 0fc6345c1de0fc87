#include "synth/corridor_scene.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace corridor {
namespace synth {
namespace {

class Random {
 public:
  explicit Random(uint32_t seed) : engine_(seed) {}
  // Uniform in [lo, hi), from raw 32-bit draws so that it is the same on every platform.
  double Uniform(double lo, double hi) { return lo + (hi - lo) * (engine_() / 4294967296.0); }
  bool Chance(double p) { return Uniform(0, 1) < p; }

 private:
  std::mt19937 engine_;
};

cv::Vec3f Mix(const cv::Vec3f& a, const cv::Vec3f& b, double t) {
  return a * static_cast<float>(1 - t) + b * static_cast<float>(t);
}

cv::Vec3f RandomColor(Random* r, double lo, double hi) {
  return cv::Vec3f(static_cast<float>(r->Uniform(lo, hi)), static_cast<float>(r->Uniform(lo, hi)),
                   static_cast<float>(r->Uniform(lo, hi)));
}

cv::Vec3f Grey(Random* r, double lo, double hi) {
  const float g = static_cast<float>(r->Uniform(lo, hi));
  return cv::Vec3f(g, g, g);
}

cv::Vec3f Clamp01(const cv::Vec3f& c) {
  return cv::Vec3f(std::min(1.0f, std::max(0.0f, c[0])), std::min(1.0f, std::max(0.0f, c[1])),
                   std::min(1.0f, std::max(0.0f, c[2])));
}

// Wood, metal, dark or wall-like (low contrast): the trims' palette.
cv::Vec3f TrimColor(Random* r, const cv::Vec3f& wall) {
  const double pick = r->Uniform(0, 1);
  if (pick < 0.3) {
    const float k = static_cast<float>(r->Uniform(0.6, 1.3));
    return Clamp01(cv::Vec3f(0.22f, 0.36f, 0.52f) * k);
  }
  if (pick < 0.55) return Grey(r, 0.55, 0.85);
  if (pick < 0.75) return Grey(r, 0.08, 0.25);
  return Clamp01(wall * static_cast<float>(r->Uniform(0.8, 1.2)));
}

// An interval [z0, z1] along one wall that a part must not cross.
struct Span {
  int side;
  double z0, z1;
};

bool Overlaps(const std::vector<Span>& spans, int side, double z0, double z1) {
  for (const Span& s : spans) {
    if (s.side == side && z0 < s.z1 && z1 > s.z0) return true;
  }
  return false;
}

// A box against the wall `side`: `gap` off the wall, `depth` into the corridor, over z and y.
Obstacle WallBox(double half, int side, double gap, double depth, double y0, double y1, double z0,
                 double z1, const cv::Vec3f& color, Obstacle::Kind kind) {
  const double wall = side * half;
  const double inner = wall - side * (gap + depth), outer = wall - side * gap;
  Obstacle box;
  box.min = Eigen::Vector3d(std::min(inner, outer), y0, z0);
  box.max = Eigen::Vector3d(std::max(inner, outer), y1, z1);
  box.color = color;
  box.kind = kind;
  return box;
}

void RemoveDoors(int side, double z0, double z1, CorridorScene* scene) {
  auto& doors = scene->doors;
  doors.erase(std::remove_if(doors.begin(), doors.end(),
                             [&](const Door& d) { return d.side == side && d.z0 < z1 && d.z1 > z0; }),
              doors.end());
}

// Rails along one wall, split where doors and pillars interrupt them.
void AddRails(const CorridorScene& scene, const std::vector<Span>& blocked, int side, double gap,
              double depth, double y0, double y1, const cv::Vec3f& color, Obstacle::Kind kind,
              std::vector<Obstacle>* out) {
  const double half = 0.5 * scene.options.width, length = scene.options.length;
  std::vector<Span> cuts;
  for (const Span& s : blocked) {
    if (s.side == side) cuts.push_back(s);
  }
  std::sort(cuts.begin(), cuts.end(), [](const Span& a, const Span& b) { return a.z0 < b.z0; });
  double z = 0.0;
  for (const Span& c : cuts) {
    if (c.z0 - z > 0.3) out->push_back(WallBox(half, side, gap, depth, y0, y1, z, c.z0, color, kind));
    z = std::max(z, c.z1);
  }
  if (length - z > 0.3) out->push_back(WallBox(half, side, gap, depth, y0, y1, z, length, color, kind));
}

void AddFurniture(const SceneOptions& o, Random* r, const std::vector<Span>& blocked,
                  CorridorScene* scene) {
  const double half = 0.5 * o.width;
  const int count = static_cast<int>(std::round(o.furniture * o.length / 4.0));
  for (int i = 0; i < count; ++i) {
    const int type = std::min(4, static_cast<int>(r->Uniform(0, 5)));
    const int side = r->Chance(0.5) ? -1 : 1;
    const double z0 = r->Uniform(1.5, o.length - 4.0);
    const double max_depth = 0.4 * o.width;
    double len = 0, depth = 0, gap = r->Uniform(0.0, 0.05), y0 = 0, y1 = 0;
    cv::Vec3f color;
    switch (type) {
      case 0:  // Bench: a low seat, wood or metal.
        len = r->Uniform(1.2, 2.0), depth = r->Uniform(0.35, 0.5), y1 = r->Uniform(0.42, 0.5);
        color = TrimColor(r, scene->wall_color);
        break;
      case 1:  // Sofa: a seat and a back.
        len = r->Uniform(1.6, 2.2), depth = r->Uniform(0.75, 0.95), y1 = r->Uniform(0.4, 0.48);
        color = RandomColor(r, 0.1, 0.6);
        break;
      case 2:  // Lockers: tall metal cabinets.
        len = r->Uniform(0.9, 3.0), depth = r->Uniform(0.35, 0.5), y1 = r->Uniform(1.7, 1.95);
        color = r->Chance(0.5) ? Grey(r, 0.4, 0.75) : RandomColor(r, 0.2, 0.6);
        break;
      case 3:  // Radiator: thin, white, raised off the floor.
        len = r->Uniform(0.6, 1.6), depth = r->Uniform(0.06, 0.14), y0 = r->Uniform(0.08, 0.15);
        y1 = y0 + r->Uniform(0.4, 0.6);
        color = Grey(r, 0.75, 0.95);
        break;
      default:  // Cart on wheels: the floor shows under it.
        len = r->Uniform(0.6, 1.0), depth = r->Uniform(0.45, 0.6), gap = r->Uniform(0.05, 0.3);
        y0 = r->Uniform(0.1, 0.2), y1 = r->Uniform(0.85, 1.0);
        color = RandomColor(r, 0.2, 0.7);
        break;
    }
    depth = std::min(depth, max_depth);
    if (Overlaps(blocked, side, z0 - 0.1, z0 + len + 0.1)) continue;
    scene->obstacles.push_back(WallBox(half, side, gap, depth, y0, y1, z0, z0 + len, color,
                                       Obstacle::kFurniture));
    if (type == 1) {
      const double back = std::min(depth, r->Uniform(0.15, 0.25));
      scene->obstacles.push_back(WallBox(half, side, gap, back, y1, r->Uniform(0.75, 0.9), z0,
                                         z0 + len, color * 0.85f, Obstacle::kFurniture));
    }
  }
}

void AddRealBuildingParts(const SceneOptions& o, Random* r, CorridorScene* scene) {
  const double half = 0.5 * o.width, frame = 0.08;
  const int one = r->Chance(0.5) ? -1 : 1;  // The wall that gets one-sided parts.
  if (o.glass_walls) {
    const bool two = r->Chance(0.3);
    for (int side = -1; side <= 1; side += 2) {
      if (!two && side != one) continue;
      for (double z = r->Uniform(1.0, 6.0); z + 3.0 < o.length - 2.0;) {
        GlassRun g;
        g.side = side;
        g.z0 = z;
        g.z1 = std::min(o.length - 2.0, z + r->Uniform(3.0, 10.0));
        g.top = r->Chance(0.6) ? o.ceiling_height
                               : std::min(o.ceiling_height - 0.1, r->Uniform(2.0, 2.4));
        g.room_depth = r->Uniform(2.0, 7.0);
        g.room_light = r->Uniform(0.4, 1.4);
        g.desk_height = r->Uniform(0.7, 0.8);
        g.mullion_spacing = r->Uniform(0.9, 1.8);
        g.mullion_width = r->Uniform(0.03, 0.08);
        g.base_height = r->Uniform(0.0, 0.12);
        g.frame_color = r->Chance(0.5) ? Grey(r, 0.12, 0.3) : Grey(r, 0.55, 0.75);
        g.room_floor_color = RandomColor(r, 0.2, 0.6);
        g.room_wall_color = RandomColor(r, 0.4, 0.9);
        g.desk_color = RandomColor(r, 0.1, 0.6);
        RemoveDoors(side, g.z0 - 0.3, g.z1 + 0.3, scene);
        scene->glass.push_back(g);
        z = g.z1 + r->Uniform(2.0, 6.0);
      }
    }
  }
  if (o.window_bands) {
    WindowBand w;
    w.side = one;
    w.sill = r->Uniform(0.8, 1.1);
    w.top = std::min(o.ceiling_height - 0.15, r->Uniform(1.8, 2.3));
    w.z0 = r->Uniform(0.5, 3.0);
    w.z1 = o.length - r->Uniform(0.0, 5.0);
    w.pane = r->Uniform(0.8, 2.0);
    w.mullion = r->Uniform(0.08, 0.4);
    w.horizon = r->Uniform(0.2, 0.6);
    w.sky_color = Clamp01(cv::Vec3f(1.0f, 0.97f, 0.92f) * static_cast<float>(r->Uniform(0.75, 1.0)));
    w.ground_color = RandomColor(r, 0.25, 0.5);
    w.frame_color = r->Chance(0.5) ? Grey(r, 0.8, 0.95) : Grey(r, 0.2, 0.35);
    RemoveDoors(w.side, 0.0, o.length, scene);
    scene->windows.push_back(w);
    const double out = r->Uniform(0.03, 0.1), thick = r->Uniform(0.02, 0.05);
    scene->obstacles.push_back(WallBox(half, w.side, 0.0, out, w.sill - thick, w.sill, w.z0 - 0.05,
                                       w.z1 + 0.05, r->Chance(0.5) ? w.frame_color : TrimColor(r, scene->wall_color),
                                       Obstacle::kSill));
  }
  std::vector<Span> blocked;
  for (const Door& d : scene->doors) blocked.push_back({d.side, d.z0 - frame - 0.05, d.z1 + frame + 0.05});
  for (const GlassRun& g : scene->glass) blocked.push_back({g.side, g.z0, g.z1});
  if (o.pillars) {
    const bool two = r->Chance(0.7);
    const double out = std::min(0.2 * o.width, r->Uniform(0.1, 0.35));
    const double along = r->Uniform(0.3, 0.6);
    const cv::Vec3f color = Clamp01(scene->wall_color * static_cast<float>(r->Uniform(0.8, 1.1)));
    std::vector<Span> pillar_spans;
    for (int side = -1; side <= 1; side += 2) {
      if (!two && side != one) continue;
      for (double z = r->Uniform(2.0, 6.0); z + along < o.length - 1.0; z += r->Uniform(3.5, 8.0)) {
        if (Overlaps(blocked, side, z - 0.05, z + along + 0.05)) continue;
        scene->obstacles.push_back(WallBox(half, side, 0.0, out, 0.0, o.ceiling_height, z,
                                           z + along, color, Obstacle::kPillar));
        pillar_spans.push_back({side, z - 0.02, z + along + 0.02});
      }
    }
    blocked.insert(blocked.end(), pillar_spans.begin(), pillar_spans.end());
  }
  if (o.furniture > 0) AddFurniture(o, r, blocked, scene);
  if (o.handrails) {
    const bool left = r->Chance(0.7), right = !left || r->Chance(0.7);
    const double top = r->Uniform(0.8, 1.1), thick = r->Uniform(0.03, 0.06);
    const double standoff = r->Uniform(0.04, 0.08);
    const cv::Vec3f color = TrimColor(r, scene->wall_color);
    for (int side = -1; side <= 1; side += 2) {
      if ((side < 0 && !left) || (side > 0 && !right)) continue;
      AddRails(*scene, blocked, side, standoff, thick, top - thick, top, color, Obstacle::kHandrail,
               &scene->obstacles);
    }
  }
  if (o.chair_rails) {
    const double centre = r->Uniform(0.8, 1.0), tall = r->Uniform(0.04, 0.08);
    const double out = r->Uniform(0.012, 0.03);
    const cv::Vec3f color = r->Chance(0.4) ? Grey(r, 0.85, 0.95) : TrimColor(r, scene->wall_color);
    for (int side = -1; side <= 1; side += 2) {
      AddRails(*scene, blocked, side, 0.0, out, centre - 0.5 * tall, centre + 0.5 * tall, color,
               Obstacle::kChairRail, &scene->obstacles);
    }
  }
  Paintwork& p = scene->paint;
  if (o.wainscot) {
    p.wainscot_height = r->Uniform(0.8, 1.2);
    const double pick = r->Uniform(0, 1);
    p.wainscot_color = pick < 0.4   ? Clamp01(scene->wall_color * static_cast<float>(r->Uniform(0.45, 0.85)))
                       : pick < 0.7 ? Clamp01(cv::Vec3f(0.25f, 0.4f, 0.55f) * static_cast<float>(r->Uniform(0.6, 1.3)))
                                    : RandomColor(r, 0.3, 0.9);
    p.wainscot_cap = r->Chance(0.5) ? r->Uniform(0.02, 0.05) : 0.0;
    p.wainscot_cap_color = TrimColor(r, scene->wall_color);
  }
  if (o.runner) {
    const double w = r->Uniform(0.35, 0.7) * o.width, centre = r->Uniform(-0.1, 0.1) * o.width;
    p.runner_x0 = centre - 0.5 * w;
    p.runner_x1 = centre + 0.5 * w;
    p.runner_color = RandomColor(r, 0.08, 0.7);
    p.runner_border = r->Chance(0.5) ? r->Uniform(0.03, 0.08) : 0.0;
    p.runner_border_color = RandomColor(r, 0.1, 0.8);
  }
  if (o.floor_stripes) {
    p.stripe_inset = r->Uniform(0.1, 0.5);
    p.stripe_width = r->Uniform(0.04, 0.12);
    const double pick = r->Uniform(0, 1);
    p.stripe_color = pick < 0.4 ? cv::Vec3f(0.1f, 0.8f, 0.9f) : pick < 0.7 ? Grey(r, 0.85, 0.95)
                                                                           : Grey(r, 0.05, 0.15);
  }
  if (o.carpet) {
    p.carpet_grain = r->Uniform(0.01, 0.03);
    p.carpet_amplitude = r->Uniform(0.08, 0.3);
  }
}
}  // namespace

CorridorScene BuildScene(const SceneOptions& options) {
  CorridorScene scene;
  scene.options = options;
  Random random(options.seed);
  // Painted walls: a light, slightly warm grey; the floor a darker, more saturated tone.
  scene.wall_color = cv::Vec3f(static_cast<float>(random.Uniform(0.62, 0.78)),
                               static_cast<float>(random.Uniform(0.68, 0.80)),
                               static_cast<float>(random.Uniform(0.72, 0.84)));
  const cv::Vec3f floor_tone(static_cast<float>(random.Uniform(0.20, 0.40)),
                             static_cast<float>(random.Uniform(0.30, 0.45)),
                             static_cast<float>(random.Uniform(0.40, 0.60)));
  scene.floor_color = Mix(scene.wall_color * 0.9f, floor_tone, options.floor_wall_contrast);
  scene.grout_color = scene.floor_color * 0.75f;
  scene.baseboard_color = scene.wall_color * static_cast<float>(1 - 0.8 * options.baseboard_contrast);
  scene.ceiling_color = cv::Vec3f(0.85f, 0.86f, 0.86f);
  scene.end_color = scene.wall_color * 0.92f;
  const double half = 0.5 * options.width;

  for (int side = -1; side <= 1; side += 2) {
    for (double z = random.Uniform(1.5, 4.0); z + 1.2 < options.length - 1.0;
         z += random.Uniform(4.0, 6.0)) {
      if (!random.Chance(options.door_density)) continue;
      Door door;
      door.side = side;
      door.z0 = z;
      door.z1 = z + random.Uniform(0.85, 1.1);
      door.height = random.Uniform(1.95, 2.15);
      door.recess = random.Uniform(0.05, 0.3);
      const double wood = random.Uniform(0, 1);
      door.leaf_color = wood < 0.5 ? cv::Vec3f(0.18f, 0.32f, 0.48f) * static_cast<float>(random.Uniform(0.7, 1.2))
                                   : cv::Vec3f(0.45f, 0.42f, 0.38f) * static_cast<float>(random.Uniform(0.6, 1.1));
      door.frame_color = scene.wall_color * static_cast<float>(random.Uniform(0.45, 0.7));
      scene.doors.push_back(door);
    }
  }
  const int obstacles = static_cast<int>(std::round(options.clutter * options.length / 3.0));
  for (int i = 0; i < obstacles; ++i) {
    const int side = random.Chance(0.5) ? -1 : 1;
    const double depth = random.Uniform(0.3, std::min(0.8, 0.35 * options.width));
    const double gap = random.Uniform(0.0, 0.15);  // Against the wall: hides the junction.
    const double z = random.Uniform(2.0, options.length - 2.0);
    Obstacle box;
    const double wall = side * half;
    const double inner = wall - side * (gap + depth), outer = wall - side * gap;
    box.min = Eigen::Vector3d(std::min(inner, outer), 0.0, z);
    box.max = Eigen::Vector3d(std::max(inner, outer), random.Uniform(0.3, 1.1),
                              z + random.Uniform(0.3, 0.9));
    box.color = cv::Vec3f(static_cast<float>(random.Uniform(0.1, 0.7)),
                          static_cast<float>(random.Uniform(0.1, 0.7)),
                          static_cast<float>(random.Uniform(0.1, 0.7)));
    scene.obstacles.push_back(box);
  }
  if (options.lights) {
    for (double z = 1.5; z + 1.2 < options.length; z += 3.0) {
      scene.lights.push_back({-0.3, 0.3, z, z + 1.2});
    }
  }
  // The parts of real buildings draw from their own stream, so that a scene without them is the
  // same as before they existed.
  Random parts(options.seed * 2654435761u + 0x9e3779b9u);
  AddRealBuildingParts(options, &parts, &scene);
  return scene;
}

}  // namespace synth
}  // namespace corridor
