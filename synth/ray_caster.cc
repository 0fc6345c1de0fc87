#include "synth/ray_caster.h"

#include <cmath>
#include <cstdint>
#include <limits>

namespace corridor {
namespace synth {
namespace {

constexpr double kEps = 1e-9;
constexpr double kGrout = 0.012;     // Grout line width, m.
constexpr double kFrameBand = 0.08;  // Door frame width on the wall, m.

// Distance of x to the nearest multiple of `period`.
double DistanceToGrid(double x, double period) {
  const double f = x / period - std::floor(x / period);
  return period * std::min(f, 1.0 - f);
}

// Low-frequency paint variation, deterministic in position.
float Paint(double z, double y, uint32_t seed) {
  const double s = 0.37 * (seed % 97);
  return static_cast<float>(1.0 + 0.035 * std::sin(1.3 * z + 0.7 * y + s) * std::sin(0.41 * z + s) +
                            0.02 * std::sin(3.1 * y - 0.9 * z));
}

void Take(double t, const Eigen::Vector3d& normal, const cv::Vec3f& albedo, bool emissive,
          Hit* best) {
  if (t > kEps && (!best->found || t < best->t)) {
    best->t = t;
    best->found = true;
    best->normal = normal;
    best->albedo = albedo;
    best->emissive = emissive;
  }
}

// A repeatable pseudo-random value in [-1, 1] for an integer cell.
double CellNoise(int64_t i, int64_t j, uint32_t seed) {
  uint64_t h = static_cast<uint64_t>(i) * 0x9E3779B97F4A7C15ull ^
               static_cast<uint64_t>(j) * 0xC2B2AE3D27D4EB4Full ^ (seed * 0x165667B19E3779F9ull);
  h ^= h >> 31;
  h *= 0xBF58476D1CE4E5B9ull;
  h ^= h >> 29;
  return (h & 0xFFFFFF) / static_cast<double>(0x7FFFFF) - 1.0;
}

cv::Vec3f FloorAlbedo(const CorridorScene& s, const Eigen::Vector3d& p) {
  const Paintwork& paint = s.paint;
  if (paint.stripe_width > 0) {
    const double half = 0.5 * s.options.width;
    const double from_wall = half - std::abs(p.x());
    if (from_wall > paint.stripe_inset && from_wall < paint.stripe_inset + paint.stripe_width) {
      return paint.stripe_color;
    }
  }
  float texture = 1.0f;
  if (paint.carpet_grain > 0) {
    const double g = paint.carpet_grain;
    const double fine = CellNoise(static_cast<int64_t>(std::floor(p.x() / g)),
                                  static_cast<int64_t>(std::floor(p.z() / g)), s.options.seed);
    texture = static_cast<float>(1.0 + paint.carpet_amplitude * fine +
                                 0.04 * std::sin(2.1 * p.z() + 1.3 * p.x()) * std::sin(0.7 * p.z()));
  }
  if (p.x() > paint.runner_x0 && p.x() < paint.runner_x1) {
    if (p.x() < paint.runner_x0 + paint.runner_border || p.x() > paint.runner_x1 - paint.runner_border) {
      return paint.runner_border_color * texture;
    }
    return paint.runner_color * texture;
  }
  if (paint.carpet_grain > 0) return s.floor_color * texture;
  const double tile = s.options.tile_size;
  // Tiles are laid from the centre line, so grout lines run along and across the corridor.
  if (DistanceToGrid(p.x() + 0.5 * tile, tile) < 0.5 * kGrout ||
      DistanceToGrid(p.z(), tile) < 0.5 * kGrout) {
    return s.grout_color;
  }
  return s.floor_color;
}

// Colour of the wall plane (side -1 or +1) at p, outside door openings.
cv::Vec3f WallAlbedo(const CorridorScene& s, int side, const Eigen::Vector3d& p) {
  for (const Door& door : s.doors) {
    if (door.side != side) continue;
    if (p.z() > door.z0 - kFrameBand && p.z() < door.z1 + kFrameBand &&
        p.y() < door.height + kFrameBand) {
      return door.frame_color;
    }
  }
  if (p.y() < s.options.baseboard_height) return s.baseboard_color;
  const Paintwork& paint = s.paint;
  if (p.y() < paint.wainscot_height) return paint.wainscot_color;
  if (p.y() < paint.wainscot_height + paint.wainscot_cap) return paint.wainscot_cap_color;
  return s.wall_color * Paint(p.z(), p.y(), s.options.seed + (side > 0 ? 7u : 0u));
}

// The door whose opening contains the wall point p, or null.
const Door* DoorAt(const CorridorScene& s, int side, const Eigen::Vector3d& p) {
  for (const Door& door : s.doors) {
    if (door.side == side && p.z() > door.z0 && p.z() < door.z1 && p.y() < door.height) return &door;
  }
  return nullptr;
}

// A ray that entered a door recess through the wall plane at t_in: where it leaves the recess box
// is the visible surface (the leaf, a jamb, the lintel or the recess floor).
void HitRecess(const CorridorScene& s, const Door& door, const Eigen::Vector3d& o,
               const Eigen::Vector3d& d, Hit* best) {
  const double wall = door.side * 0.5 * s.options.width;
  const double back = wall + door.side * door.recess;
  double t = (back - o.x()) / d.x();
  Eigen::Vector3d normal(-door.side, 0, 0);
  cv::Vec3f albedo = door.leaf_color;
  if (d.y() > kEps) {
    const double ty = (door.height - o.y()) / d.y();
    if (ty < t) t = ty, normal = Eigen::Vector3d(0, -1, 0), albedo = door.frame_color;
  } else if (d.y() < -kEps) {
    const double ty = -o.y() / d.y();
    if (ty < t) t = ty, normal = Eigen::Vector3d(0, 1, 0), albedo = s.floor_color;
  }
  if (d.z() > kEps) {
    const double tz = (door.z1 - o.z()) / d.z();
    if (tz < t) t = tz, normal = Eigen::Vector3d(0, 0, -1), albedo = door.frame_color;
  } else if (d.z() < -kEps) {
    const double tz = (door.z0 - o.z()) / d.z();
    if (tz < t) t = tz, normal = Eigen::Vector3d(0, 0, 1), albedo = door.frame_color;
  }
  Take(t, normal, albedo, false, best);
}

// The glass run whose pane contains the wall point p, or null.
const GlassRun* GlassAt(const CorridorScene& s, int side, const Eigen::Vector3d& p) {
  for (const GlassRun& g : s.glass) {
    if (g.side == side && p.z() > g.z0 && p.z() < g.z1 && p.y() >= 0 && p.y() < g.top) return &g;
  }
  return nullptr;
}

// Colour seen through the glass at p (on the wall plane) along d: the frame where it is painted,
// else the room behind (its back wall, floor, ceiling or ends) dimmed or brightened by its light
// and a faint reflection of the corridor's wall.
cv::Vec3f GlassAlbedo(const CorridorScene& s, const GlassRun& g, const Eigen::Vector3d& p,
                      const Eigen::Vector3d& d) {
  const double along = p.z() - g.z0;
  if (p.y() < g.base_height || g.top - p.y() < g.mullion_width ||
      DistanceToGrid(along, g.mullion_spacing) < 0.5 * g.mullion_width ||
      g.z1 - p.z() < 0.5 * g.mullion_width) {
    return g.frame_color;
  }
  const double wall = g.side * 0.5 * s.options.width;
  double t = (wall + g.side * g.room_depth - p.x()) / d.x();
  int surface = 0;  // 0 back wall, 1 floor, 2 ceiling, 3 end.
  if (d.y() < -kEps && -p.y() / d.y() < t) t = -p.y() / d.y(), surface = 1;
  if (d.y() > kEps && (s.options.ceiling_height - p.y()) / d.y() < t) {
    t = (s.options.ceiling_height - p.y()) / d.y(), surface = 2;
  }
  if (std::abs(d.z()) > kEps) {
    const double tz = ((d.z() > 0 ? g.z1 + 2.0 : g.z0 - 2.0) - p.z()) / d.z();
    if (tz < t) t = tz, surface = 3;
  }
  const Eigen::Vector3d q = p + t * d;
  cv::Vec3f behind;
  if (surface == 1) {
    behind = g.room_floor_color;
  } else if (surface == 2) {
    behind = cv::Vec3f(0.8f, 0.8f, 0.8f);
  } else if (surface == 3) {
    behind = g.room_wall_color * 0.85f;
  } else if (DistanceToGrid(q.z() - g.z0, 1.5) < 0.03) {
    behind = g.desk_color * 0.5f;  // Shelf uprights.
  } else {
    behind = q.y() < g.desk_height ? g.desk_color : g.room_wall_color;
  }
  return behind * static_cast<float>(0.85 * g.room_light) + s.wall_color * 0.1f;
}

// The window band's pane or frame at the wall point p, or false when p is plain wall.
bool WindowAt(const CorridorScene& s, int side, const Eigen::Vector3d& p, cv::Vec3f* albedo,
              bool* emissive) {
  constexpr double kBandFrame = 0.04;
  for (const WindowBand& w : s.windows) {
    if (w.side != side || p.z() < w.z0 || p.z() > w.z1 || p.y() < w.sill || p.y() > w.top) continue;
    const double period = w.pane + w.mullion;
    const double f = (p.z() - w.z0) - period * std::floor((p.z() - w.z0) / period);
    *emissive = !(f < w.mullion || p.y() < w.sill + kBandFrame || p.y() > w.top - kBandFrame);
    if (!*emissive) {
      *albedo = w.frame_color;
    } else {
      *albedo = (p.y() - w.sill) / (w.top - w.sill) < w.horizon ? w.ground_color : w.sky_color;
    }
    return true;
  }
  return false;
}

// Slab test against an obstacle.
void HitObstacle(const Obstacle& box, const Eigen::Vector3d& o, const Eigen::Vector3d& d,
                 Hit* best) {
  double t_near = -std::numeric_limits<double>::infinity();
  double t_far = std::numeric_limits<double>::infinity();
  int axis_near = -1;
  double sign_near = 0;
  for (int a = 0; a < 3; ++a) {
    if (std::abs(d[a]) < kEps) {
      if (o[a] < box.min[a] || o[a] > box.max[a]) return;
      continue;
    }
    double t0 = (box.min[a] - o[a]) / d[a], t1 = (box.max[a] - o[a]) / d[a];
    double sign = -1;  // Entering through the min face: normal points to -axis.
    if (t0 > t1) std::swap(t0, t1), sign = 1;
    if (t0 > t_near) t_near = t0, axis_near = a, sign_near = sign;
    t_far = std::min(t_far, t1);
  }
  if (t_near > t_far || t_far < kEps || axis_near < 0) return;
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  normal[axis_near] = sign_near;
  Take(t_near, normal, box.color, false, best);
}

}  // namespace

Hit CastRay(const CorridorScene& s, const Eigen::Vector3d& o, const Eigen::Vector3d& d) {
  Hit best;
  const double half = 0.5 * s.options.width, ceiling = s.options.ceiling_height;
  if (d.y() < -kEps) {
    const double t = -o.y() / d.y();
    Take(t, Eigen::Vector3d(0, 1, 0), FloorAlbedo(s, o + t * d), false, &best);
  } else if (d.y() > kEps) {
    const double t = (ceiling - o.y()) / d.y();
    const Eigen::Vector3d p = o + t * d;
    bool lit = false;
    for (const Light& light : s.lights) {
      lit |= p.x() > light.x0 && p.x() < light.x1 && p.z() > light.z0 && p.z() < light.z1;
    }
    Take(t, Eigen::Vector3d(0, -1, 0), lit ? cv::Vec3f(1.0f, 1.0f, 0.97f) : s.ceiling_color, lit,
         &best);
  }
  if (d.z() > kEps) {
    Take((s.options.length - o.z()) / d.z(), Eigen::Vector3d(0, 0, -1), s.end_color, false, &best);
  }
  if (std::abs(d.x()) > kEps) {
    const int side = d.x() < 0 ? -1 : 1;
    const double t = (side * half - o.x()) / d.x();
    const Eigen::Vector3d p = o + t * d;
    if (!best.found || t < best.t) {
      const Door* door = p.y() > 0 ? DoorAt(s, side, p) : nullptr;
      const GlassRun* glass = door == nullptr ? GlassAt(s, side, p) : nullptr;
      const Eigen::Vector3d normal(-side, 0, 0);
      cv::Vec3f albedo;
      bool emissive = false;
      if (door != nullptr) {
        HitRecess(s, *door, o, d, &best);
      } else if (glass != nullptr) {
        Take(t, normal, GlassAlbedo(s, *glass, p, d), false, &best);  // The glass plane is the surface.
      } else if (WindowAt(s, side, p, &albedo, &emissive)) {
        Take(t, normal, albedo, emissive, &best);
      } else {
        Take(t, normal, WallAlbedo(s, side, p), false, &best);
      }
    }
  }
  for (const Obstacle& box : s.obstacles) HitObstacle(box, o, d, &best);
  return best;
}

}  // namespace synth
}  // namespace corridor
