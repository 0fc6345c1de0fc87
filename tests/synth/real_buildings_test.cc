// The parts of real buildings against positions and depths computed by hand: each part is where
// its options put it in the image, solids have the depth of their faces, paint and glass keep the
// wall's and floor's depth, and a rolled camera's truth is the hand-rotated ray's.
#include <algorithm>
#include <cmath>
#include <set>

#include <gtest/gtest.h>

#include "synth/corridor_renderer.h"
#include "synth/corridor_scene.h"
#include "synth/real_buildings.h"

namespace corridor {
namespace synth {
namespace {

Camera TestCamera() {
  Camera c;
  c.image_width = 200;
  c.image_height = 150;
  c.fx = c.fy = 120;
  c.cx = 99.5;
  c.cy = 74.5;
  c.mount_height = 0.66;
  return c;
}

SceneOptions Plain(uint32_t seed) {
  SceneOptions o;
  o.width = 2.4;
  o.ceiling_height = 2.7;
  o.length = 60;
  o.door_density = 0;
  o.lights = false;
  o.noise_sigma = 0;
  o.blur_sigma = 0;
  o.seed = seed;
  return o;
}

// TestCamera with pixels 3.3 times finer, so that a part a few centimetres tall covers several
// rows.
Camera FineCamera() {
  Camera camera = TestCamera();
  camera.image_width = 480;
  camera.image_height = 360;
  camera.fx = camera.fy = 400;
  camera.cx = 239.5;
  camera.cy = 179.5;
  return camera;
}

// Pixel (column, row) of a world point for a level, unrolled camera looking down the corridor.
cv::Point2d Project(const Camera& c, const CameraPose& pose, double x, double y, double z) {
  const double depth = z - pose.distance;
  return {c.cx + c.fx * (x - pose.offset) / depth, c.cy + c.fy * (pose.height - y) / depth};
}

const Obstacle* FirstOfKind(const CorridorScene& scene, Obstacle::Kind kind, int side) {
  for (const Obstacle& box : scene.obstacles) {
    const int box_side = box.min.x() + box.max.x() < 0 ? -1 : 1;
    if (box.kind == kind && (side == 0 || box_side == side)) return &box;
  }
  return nullptr;
}

TEST(RealBuildingsTest, HandrailsAndChairRailsStayInTheirRanges) {
  int handrails = 0, chair_rails = 0;
  for (uint32_t seed = 1; seed <= 20; ++seed) {
    SceneOptions o = Plain(seed);
    o.door_density = 0.5;
    o.handrails = o.chair_rails = true;
    const CorridorScene scene = BuildScene(o);
    const double half = 0.5 * o.width;
    for (const Obstacle& box : scene.obstacles) {
      const int side = box.min.x() + box.max.x() < 0 ? -1 : 1;
      const double wall_gap = half - std::max(std::abs(box.min.x()), std::abs(box.max.x()));
      const double thick = box.max.x() - box.min.x();
      if (box.kind == Obstacle::kHandrail) {
        ++handrails;
        EXPECT_GE(box.max.y(), 0.8 - 1e-9);
        EXPECT_LE(box.max.y(), 1.1 + 1e-9);
        EXPECT_GE(wall_gap, 0.04 - 1e-9);
        EXPECT_LE(wall_gap, 0.08 + 1e-9);
        EXPECT_GE(thick, 0.03 - 1e-9);
        EXPECT_LE(thick, 0.06 + 1e-9);
      } else if (box.kind == Obstacle::kChairRail) {
        ++chair_rails;
        EXPECT_NEAR(wall_gap, 0.0, 1e-9);
        EXPECT_GE(0.5 * (box.min.y() + box.max.y()), 0.8 - 1e-9);
        EXPECT_LE(0.5 * (box.min.y() + box.max.y()), 1.0 + 1e-9);
      } else {
        continue;
      }
      // Rails break at doors: no rail crosses a door opening on its wall.
      for (const Door& door : scene.doors) {
        if (door.side != side) continue;
        EXPECT_TRUE(box.max.z() <= door.z0 || box.min.z() >= door.z1)
            << "rail " << box.min.z() << ".." << box.max.z() << " crosses a door at " << door.z0;
      }
    }
  }
  EXPECT_GT(handrails, 20);
  EXPECT_GT(chair_rails, 40);
}

// A handrail on the left wall: its inner face shows at the rows where the rail's height projects,
// with the face's depth; a few rows above and below, the wall.
TEST(RealBuildingsTest, HandrailShowsAtItsProjectedHeight) {
  SceneOptions o = Plain(3);
  o.handrails = true;
  CorridorScene scene = BuildScene(o);
  const Obstacle* found = FirstOfKind(scene, Obstacle::kHandrail, -1);
  if (found == nullptr) found = FirstOfKind(scene, Obstacle::kHandrail, 1);
  ASSERT_NE(found, nullptr);
  Obstacle rail = *found;
  rail.color = cv::Vec3f(0.05f, 0.05f, 0.05f);  // Dark against the light wall.
  scene.obstacles = {rail};
  const int side = rail.min.x() + rail.max.x() < 0 ? -1 : 1;
  const Camera camera = FineCamera();
  const CameraPose pose{0.0, 0.0, 0.0, 0.66, 2.0};
  Frame frame;
  ASSERT_TRUE(RenderFrame(scene, camera, pose, &frame).ok());
  const double face_x = side < 0 ? rail.max.x() : rail.min.x();
  const double wall_x = side * 0.5 * o.width;
  int checked = 0;
  for (double ahead : {2.5, 3.0, 3.5}) {
    const double z = pose.distance + ahead;
    const cv::Point2d p = Project(camera, pose, face_x, 0.5 * (rail.min.y() + rail.max.y()), z);
    const int u = static_cast<int>(std::lround(p.x)), v = static_cast<int>(std::lround(p.y));
    ASSERT_TRUE(u >= 0 && u < camera.image_width && v >= 0 && v < camera.image_height);
    const double ray_x = (u - camera.cx) / camera.fx, ray_y = (v - camera.cy) / camera.fy;
    const double face_depth = (face_x - pose.offset) / ray_x;
    const double y_hit = pose.height - ray_y * face_depth;
    const double margin = 0.3 * face_depth / camera.fy;  // The 2x2 samples stay on the face.
    if (y_hit < rail.min.y() + margin || y_hit > rail.max.y() - margin) continue;
    EXPECT_NEAR(frame.depth.at<float>(v, u), face_depth, 1e-4 * face_depth) << "z " << z;
    const cv::Vec3b rail_bgr = frame.bgr.at<cv::Vec3b>(v, u);
    EXPECT_LT(rail_bgr[0] + rail_bgr[1] + rail_bgr[2], 60) << "z " << z;
    // 0.15 m above and below the rail: the wall, lighter, at the wall's depth.
    for (double dy : {-0.15, 0.15}) {
      const double y = dy < 0 ? rail.min.y() + dy : rail.max.y() + dy;
      const cv::Point2d q = Project(camera, pose, wall_x, y, z);
      const int vq = static_cast<int>(std::lround(q.y));
      const double wall_depth = (wall_x - pose.offset) / ray_x;
      EXPECT_NEAR(frame.depth.at<float>(vq, u), wall_depth, 1e-4 * wall_depth);
      const cv::Vec3b wall_bgr = frame.bgr.at<cv::Vec3b>(vq, u);
      EXPECT_GT(wall_bgr[0] + wall_bgr[1] + wall_bgr[2], 200);
    }
    ++checked;
  }
  EXPECT_GE(checked, 2);
}

// A baseboard of the baseboard class's height shows dark up to that height on the wall, where
// the camera projects it by hand, and the wall's own colour above it.
TEST(RealBuildingsTest, BaseboardShowsUpToItsHeight) {
  for (double height : {0.05, 0.2}) {
    SceneOptions o = Plain(5);
    o.baseboard_height = height;
    o.baseboard_contrast = 0.8;
    const CorridorScene scene = BuildScene(o);
    const Camera camera = FineCamera();
    const CameraPose pose{0.0, 0.0, 0.0, 0.66, 2.0};
    Frame frame;
    ASSERT_TRUE(RenderFrame(scene, camera, pose, &frame).ok());
    const double wall_x = -0.5 * o.width;
    for (double ahead : {3.0, 4.0, 5.0}) {
      const double z = pose.distance + ahead;
      const auto brightness = [&](double y) {
        const cv::Point2d p = Project(camera, pose, wall_x, y, z);
        const int u = static_cast<int>(std::lround(p.x)), v = static_cast<int>(std::lround(p.y));
        EXPECT_TRUE(u >= 0 && u < camera.image_width && v >= 0 && v < camera.image_height);
        const cv::Vec3b bgr = frame.bgr.at<cv::Vec3b>(std::clamp(v, 0, camera.image_height - 1),
                                                      std::clamp(u, 0, camera.image_width - 1));
        return bgr[0] + bgr[1] + bgr[2];
      };
      const int below = brightness(0.6 * height), above = brightness(height + 0.06);
      // Contrast 0.8 makes the baseboard 0.36 of the wall's colour.
      EXPECT_LT(below, 0.5 * above) << "height " << height << " z " << z;
    }
  }
}

// The face of a generated bench (or other furniture) and of a pillar toward the corridor's centre
// has the depth of that plane along the pixel's ray.
TEST(RealBuildingsTest, FurnitureAndPillarFacesHaveTheirDepth) {
  for (Obstacle::Kind kind : {Obstacle::kFurniture, Obstacle::kPillar}) {
    int checked = 0;
    for (uint32_t seed = 1; seed <= 6; ++seed) {
      SceneOptions o = Plain(seed);
      o.furniture = kind == Obstacle::kFurniture ? 1.0 : 0.0;
      o.pillars = kind == Obstacle::kPillar;
      CorridorScene scene = BuildScene(o);
      const Obstacle* found = FirstOfKind(scene, kind, 0);
      ASSERT_NE(found, nullptr) << "seed " << seed;
      const Obstacle box = *found;
      scene.obstacles = {box};
      const int side = box.min.x() + box.max.x() < 0 ? -1 : 1;
      const double face_x = side < 0 ? box.max.x() : box.min.x();
      EXPECT_LE(std::abs(face_x), 0.5 * o.width) << "inside the corridor";
      EXPECT_LE(box.max.x() - box.min.x(), 0.4 * o.width + 1e-9);
      const double zc = 0.5 * (box.min.z() + box.max.z()), yc = 0.5 * (box.min.y() + box.max.y());
      const CameraPose pose{0.0, 0.0, 0.0, 0.66, std::max(0.0, zc - 3.0)};
      const Camera camera = TestCamera();
      Frame frame;
      ASSERT_TRUE(RenderFrame(scene, camera, pose, &frame).ok());
      const cv::Point2d p = Project(camera, pose, face_x, yc, zc);
      const int u = static_cast<int>(std::lround(p.x)), v = static_cast<int>(std::lround(p.y));
      ASSERT_TRUE(u >= 0 && u < camera.image_width && v >= 0 && v < camera.image_height);
      const double ray_x = (u - camera.cx) / camera.fx, ray_y = (v - camera.cy) / camera.fy;
      const double depth = (face_x - pose.offset) / ray_x;
      const double y = pose.height - ray_y * depth, z = pose.distance + depth;
      if (y < box.min.y() + 0.01 || y > box.max.y() - 0.01 || z < box.min.z() + 0.01 ||
          z > box.max.z() - 0.01) {
        continue;  // The rounded pixel's ray misses this face.
      }
      EXPECT_NEAR(frame.depth.at<float>(v, u), depth, 1e-4 * depth) << "seed " << seed;
      // Nearer than the wall behind it.
      EXPECT_LT(depth, (side * 0.5 * o.width - pose.offset) / ray_x);
      ++checked;
    }
    EXPECT_GE(checked, 4) << "kind " << kind;
  }
}

// Glass: the pixel's truth is the glass (wall) plane's depth; its colour comes from the room
// behind, so it changes with that room's light while the depth does not.
TEST(RealBuildingsTest, GlassPixelHasTheWallPlaneDepthAndTheRoomsColour) {
  SceneOptions o = Plain(5);
  o.glass_walls = true;
  CorridorScene bright = BuildScene(o);
  ASSERT_FALSE(bright.glass.empty());
  GlassRun& run = bright.glass.front();
  run.room_light = 1.4;
  CorridorScene dark = bright;
  dark.glass.front().room_light = 0.4;
  const double z = run.z0 + 0.5 * run.mullion_spacing, y = 1.3;  // Between two mullions.
  ASSERT_LT(z, run.z1 - 0.1);
  const double wall_x = run.side * 0.5 * o.width;
  const CameraPose pose{0.0, 0.0, 0.0, 0.66, std::max(0.0, z - 2.5)};
  const Camera camera = TestCamera();
  Frame a, b;
  ASSERT_TRUE(RenderFrame(bright, camera, pose, &a).ok());
  ASSERT_TRUE(RenderFrame(dark, camera, pose, &b).ok());
  const cv::Point2d p = Project(camera, pose, wall_x, y, z);
  const int u = static_cast<int>(std::lround(p.x)), v = static_cast<int>(std::lround(p.y));
  const double ray_x = (u - camera.cx) / camera.fx;
  const double depth = (wall_x - pose.offset) / ray_x;
  EXPECT_NEAR(a.depth.at<float>(v, u), depth, 1e-4 * depth);
  EXPECT_NEAR(b.depth.at<float>(v, u), depth, 1e-4 * depth);
  EXPECT_GT(cv::norm(cv::Vec3i(a.bgr.at<cv::Vec3b>(v, u)) - cv::Vec3i(b.bgr.at<cv::Vec3b>(v, u))),
            40.0);
  // The whole depth map is the glass-free corridor's: nothing behind the glass is in the truth.
  CorridorScene solid = bright;
  solid.glass.clear();
  Frame c;
  ASSERT_TRUE(RenderFrame(solid, camera, pose, &c).ok());
  EXPECT_EQ(cv::norm(a.depth, c.depth, cv::NORM_INF), 0.0);
  EXPECT_GT(cv::norm(a.bgr, c.bgr, cv::NORM_L1), 0.0);
}

// Wainscot, runner, stripes and carpet are paint: the depth is that of the bare corridor, only
// the colours change. Window panes are paint on the wall plane too; only their sill is nearer.
TEST(RealBuildingsTest, PaintKeepsTheDepthAndSillsAreNearer) {
  const Camera camera = TestCamera();
  const CameraPose pose{0.05, 0.06, 0.2, 0.66, 3.0};
  SceneOptions bare = Plain(9);
  Frame plain;
  ASSERT_TRUE(RenderFrame(bare, camera, pose, &plain).ok());
  SceneOptions painted = bare;
  painted.wainscot = painted.runner = painted.floor_stripes = painted.carpet = true;
  Frame paint;
  ASSERT_TRUE(RenderFrame(painted, camera, pose, &paint).ok());
  EXPECT_EQ(cv::norm(plain.depth, paint.depth, cv::NORM_INF), 0.0);
  cv::Mat diff;
  cv::absdiff(plain.bgr, paint.bgr, diff);
  EXPECT_GT(cv::countNonZero(diff.reshape(1)), camera.image_width * camera.image_height / 4);

  SceneOptions windows = bare;
  windows.window_bands = true;
  Frame window;
  ASSERT_TRUE(RenderFrame(windows, camera, pose, &window).ok());
  int nearer = 0, farther = 0;
  for (int v = 0; v < camera.image_height; ++v) {
    for (int u = 0; u < camera.image_width; ++u) {
      const float d0 = plain.depth.at<float>(v, u), d1 = window.depth.at<float>(v, u);
      nearer += d1 < d0 - 1e-6f;
      farther += d1 > d0 + 1e-6f;
    }
  }
  EXPECT_GT(nearer, 0);   // The sill.
  EXPECT_EQ(farther, 0);  // Panes are on the wall plane.
  EXPECT_LT(nearer, camera.image_width * camera.image_height / 20);
}

// A glossy floor, by hand for a level camera looking straight down the corridor: a wall column
// has one depth Z, and the floor at row v (depth Zf = f h / (v - cy)) mirrors the wall point that
// the matte image shows at row 2 (cy + f h / Z) - v of the same column (its height mirrored about
// the floor). Without falloff the glossy floor is (1 - s) floor + s that wall pixel, s the gloss,
// times exp(-d / reach) on a satin floor, d = (Z - Zf) |(x, y, 1)| the mirrored ray's length to
// the wall; nothing else changes. Renders with `reach`, compares with the colours `expected_reach`
// gives; counts the floor pixels checked and those within 3 levels.
struct MirrorCheck {
  int off_floor = 0, off_floor_same = 0, mirrored = 0, mirrored_close = 0;
};
MirrorCheck CheckMirror(double gloss, double reach, double expected_reach) {
  const Camera camera = TestCamera();
  // 0.75 m from the right wall: its junction reaches the image's bottom inside the image.
  const CameraPose pose{0.0, 0.0, 0.45, 0.66, 3.0};
  SceneOptions matte_options = Plain(5);
  matte_options.falloff = 0;
  matte_options.baseboard_contrast = 0.8;
  SceneOptions glossy_options = matte_options;
  glossy_options.floor_gloss = gloss;
  glossy_options.floor_gloss_reach = reach;
  Frame matte, glossy;
  MirrorCheck out;
  if (!RenderFrame(matte_options, camera, pose, &matte).ok() ||
      !RenderFrame(glossy_options, camera, pose, &glossy).ok()) {
    ADD_FAILURE() << "render failed";
    return out;
  }
  EXPECT_EQ(cv::norm(matte.depth, glossy.depth, cv::NORM_INF), 0.0);
  const double f = camera.fy, h = pose.height;
  // The floor's pixels, by the depth of the floor plane at their row.
  cv::Mat floor_mask(camera.image_height, camera.image_width, CV_8U, cv::Scalar(0));
  for (int v = 0; v < camera.image_height; ++v) {
    for (int u = 0; u < camera.image_width; ++u) {
      const double depth = matte.depth.at<float>(v, u), y = (v - camera.cy) / f;
      floor_mask.at<uchar>(v, u) = y > 0 && std::abs(depth - h / y) < 1e-4 * depth ? 255 : 0;
    }
  }
  cv::Mat near_floor;  // A pixel's samples may hit the floor up to a pixel away.
  cv::dilate(floor_mask, near_floor, cv::Mat::ones(3, 3, CV_8U));
  for (int v = 1; v < camera.image_height - 1; ++v) {
    for (int u = 1; u < camera.image_width - 1; ++u) {
      const cv::Vec3b m = matte.bgr.at<cv::Vec3b>(v, u), g = glossy.bgr.at<cv::Vec3b>(v, u);
      if (!near_floor.at<uchar>(v, u)) {
        ++out.off_floor;
        out.off_floor_same += m == g;
        continue;
      }
      if (!floor_mask.at<uchar>(v, u)) continue;
      // The wall column's depth: the depth at the row of the camera's height (the horizon).
      const double wall = matte.depth.at<float>(static_cast<int>(std::lround(camera.cy)), u);
      const int vm = static_cast<int>(std::lround(2 * (camera.cy + f * h / wall) - v));
      if (vm < 1 || vm >= camera.image_height - 1 || vm >= v - 2) continue;
      // Only where the mirrored row is on that wall, a pixel away from the floor (the samples of
      // a pixel near an edge see both sides).
      bool on_wall = std::abs(matte.depth.at<float>(vm, u) - wall) < 0.02 * wall;
      for (int dv = -1; dv <= 1; ++dv) {
        for (int du = -1; du <= 1; ++du) on_wall &= !floor_mask.at<uchar>(vm + dv, u + du);
      }
      if (!on_wall) continue;
      const double x = (u - camera.cx) / camera.fx, y = (v - camera.cy) / f;
      const double length = (wall - h / y) * std::sqrt(x * x + y * y + 1);
      const double share =
          expected_reach > 0 ? gloss * std::exp(-length / expected_reach) : gloss;
      const cv::Vec3b w = matte.bgr.at<cv::Vec3b>(vm, u);
      ++out.mirrored;
      bool close = true;
      for (int c = 0; c < 3; ++c) close &= std::abs(g[c] - ((1 - share) * m[c] + share * w[c])) <= 3.0;
      out.mirrored_close += close;
    }
  }
  return out;
}

TEST(RealBuildingsTest, AGlossyFloorMirrorsTheWallAndKeepsTheDepth) {
  const MirrorCheck c = CheckMirror(0.5, 0.0, 0.0);
  EXPECT_EQ(c.off_floor_same, c.off_floor);  // Walls and ceiling are untouched.
  EXPECT_GT(c.mirrored, 200);
  EXPECT_GE(c.mirrored_close, 0.9 * c.mirrored) << c.mirrored_close << " of " << c.mirrored;
}

// A satin floor: the same mirror, its share fading along the mirrored ray; and it does fade: the
// mirror's own colours (no fading) do not fit it.
TEST(RealBuildingsTest, ASatinFloorsReflectionFadesAlongTheMirroredRay) {
  const MirrorCheck c = CheckMirror(0.6, 0.15, 0.15);
  EXPECT_EQ(c.off_floor_same, c.off_floor);
  EXPECT_GT(c.mirrored, 200);
  EXPECT_GE(c.mirrored_close, 0.9 * c.mirrored) << c.mirrored_close << " of " << c.mirrored;
  const MirrorCheck mirror = CheckMirror(0.6, 0.15, 0.0);
  EXPECT_LT(mirror.mirrored_close, 0.5 * mirror.mirrored);
}

// geometry.md by hand: n = (0, cos t, sin t), m = (cos p, sin t sin p, -cos t sin p) for the
// unrolled ray; a rolled camera's pixel ray is first turned back by the roll by hand.
TEST(RealBuildingsTest, RolledCameraTruthIsTheHandRotatedRays) {
  const Camera camera = TestCamera();
  SceneOptions o = Plain(1);
  o.door_density = 0;
  for (double roll : {0.05, -0.03}) {
    const CameraPose pose{0.12, 0.07, 0.15, 1.6, 3.0, roll};
    Frame frame;
    ASSERT_TRUE(RenderFrame(o, camera, pose, &frame).ok());
    const double t = pose.pitch, p = pose.yaw, h = pose.height;
    const double d_left = 0.5 * o.width + pose.offset, d_right = 0.5 * o.width - pose.offset;
    int floor_checked = 0, wall_checked = 0;
    for (int v = 0; v < camera.image_height; v += 3) {
      for (int u = 0; u < camera.image_width; u += 3) {
        const double x = (u - camera.cx) / camera.fx, y = (v - camera.cy) / camera.fy;
        const double x1 = std::cos(roll) * x + std::sin(roll) * y;
        const double y1 = -std::sin(roll) * x + std::cos(roll) * y;
        const double nr = std::cos(t) * y1 + std::sin(t);
        const double mr = std::cos(p) * x1 + std::sin(t) * std::sin(p) * y1 - std::cos(t) * std::sin(p);
        const double floor = nr > 0 ? h / nr : INFINITY;
        const double wall = mr < 0 ? -d_left / mr : (mr > 0 ? d_right / mr : INFINITY);
        const double ceiling = nr < 0 ? (h - o.ceiling_height) / nr : INFINITY;
        const float got = frame.depth.at<float>(v, u);
        if (floor < wall && floor < ceiling && floor < 30) {
          EXPECT_NEAR(got, floor, 1e-4 * floor) << u << "," << v;
          ++floor_checked;
        } else if (wall < floor && wall < ceiling && wall < 30) {
          EXPECT_NEAR(got, wall, 1e-4 * wall) << u << "," << v;
          ++wall_checked;
        }
      }
    }
    EXPECT_GT(floor_checked, 200);
    EXPECT_GT(wall_checked, 200);
    // The truth geometry carries no roll: it is the corridor's, as without the nuisance.
    EXPECT_EQ(frame.truth.pitch, pose.pitch);
    EXPECT_EQ(frame.truth.camera_height, pose.height);
  }
  Frame frame;
  EXPECT_FALSE(RenderFrame(o, camera, {0, 0, 0, 0.66, 3.0, 0.7}, &frame).ok());
}

TEST(RealBuildingsTest, PresetClassesHaveTheirPartsAndCameras) {
  std::vector<ScenePreset> presets;
  RealBuildingsOptions options;
  ASSERT_TRUE(RealBuildingsPreset("all", options, &presets).ok());
  EXPECT_EQ(presets.size(), RealBuildingClasses().size() * 10u);
  std::set<uint32_t> seeds;
  for (const auto& preset : presets) {
    const SceneOptions& s = preset.scene;
    std::string why;
    EXPECT_TRUE(s.Check(&why)) << why;
    EXPECT_EQ(preset.poses.size(), 20u);
    EXPECT_EQ(preset.camera.image_width, 640);
    EXPECT_EQ(preset.camera.image_height, 480);
    seeds.insert(s.seed);
    const std::string cls = preset.name.substr(0, preset.name.find("_s"));
    if (cls == "rail") {
      EXPECT_TRUE(s.handrails || s.chair_rails) << preset.name;
    }
    if (cls == "wainscot") {
      EXPECT_TRUE(s.wainscot);
    }
    if (cls == "furniture") {
      EXPECT_GE(s.furniture, 0.5);
    }
    if (cls == "floor") {
      EXPECT_TRUE(s.runner || s.floor_stripes);
    }
    if (cls == "carpet") {
      EXPECT_TRUE(s.carpet);
    }
    if (cls == "glass") {
      EXPECT_TRUE(s.glass_walls);
    }
    if (cls == "windows") {
      EXPECT_TRUE(s.window_bands);
    }
    if (cls == "pillars") {
      EXPECT_TRUE(s.pillars);
    }
    if (cls != "mix" && cls != "rail") {
      EXPECT_FALSE(s.handrails) << preset.name;
    }
    if (cls == "glossy") {
      EXPECT_GE(s.floor_gloss, 0.25) << preset.name;
      EXPECT_LE(s.floor_gloss, 0.6) << preset.name;
    } else if (cls == "satin") {
      EXPECT_GE(s.floor_gloss, 0.3) << preset.name;
      EXPECT_LE(s.floor_gloss, 0.7) << preset.name;
      EXPECT_GE(s.floor_gloss_reach, 0.03) << preset.name;
      EXPECT_LE(s.floor_gloss_reach, 0.3) << preset.name;
    } else {
      EXPECT_EQ(s.floor_gloss, 0.0) << preset.name;
    }
    if (cls != "satin") {
      EXPECT_EQ(s.floor_gloss_reach, 0.0) << preset.name;
    }
    if (cls == "baseboard") {
      EXPECT_GE(s.baseboard_height, 0.04) << preset.name;
      EXPECT_LE(s.baseboard_height, 0.22) << preset.name;
      EXPECT_LE(s.baseboard_contrast, 0.9) << preset.name;
    } else {
      EXPECT_EQ(s.baseboard_height, SceneOptions().baseboard_height) << preset.name;
      EXPECT_GE(s.baseboard_contrast, 0.2) << preset.name;
      EXPECT_LE(s.baseboard_contrast, 0.8) << preset.name;
    }
    for (const CameraPose& pose : preset.poses) {
      EXPECT_EQ(pose.height, preset.camera.mount_height);
      if (cls == "head") {
        EXPECT_GE(pose.height, 1.4);
        EXPECT_LE(pose.height, 1.8);
        EXPECT_LE(pose.pitch, 30 * M_PI / 180 + 1e-12);
        EXPECT_GE(pose.pitch, 5 * M_PI / 180 - 1e-12);
        EXPECT_LE(std::abs(pose.roll), 3 * M_PI / 180 + 1e-12);
      } else if (cls == "low") {
        EXPECT_GE(pose.height, 0.2);
        EXPECT_LE(pose.height, 0.5);
      }
      if (cls != "head" && cls != "mix") {
        EXPECT_EQ(pose.roll, 0.0);
      }
      EXPECT_LT(pose.distance, s.length - 10.0);
    }
  }
  EXPECT_EQ(seeds.size(), presets.size());  // Every scene has its own seed.
  std::vector<ScenePreset> one;
  ASSERT_TRUE(RealBuildingsPreset("glass", options, &one).ok());
  EXPECT_EQ(one.size(), 10u);
  EXPECT_EQ(one.front().scene.seed, RealBuildingSeed("glass"));
  EXPECT_EQ(RealBuildingsPreset("sofa", options, &one).code(), StatusCode::kInvalidArgument);
}

}  // namespace
}  // namespace synth
}  // namespace corridor
