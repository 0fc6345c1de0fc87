// corridor/markers: every corner of the floor, walls, ceiling and end wall, against corners
// computed here by hand from the geometry (geometry.md sections 1-2: P_C = R_x(theta) R_y(phi) P_W,
// matrices written out), and against the surfaces' plane equations in the camera frame.

#include <cmath>

#include <gtest/gtest.h>

#include "ros/corridor_markers.h"

namespace corridor {
namespace {

struct Point3 {
  double x, y, z;
};

// P_C = R_x(theta) R_y(phi) P_W, the matrices of geometry.md written out.
Point3 ToCamera(const CorridorGeometry& g, Point3 w) {
  const double cp = std::cos(g.yaw), sp = std::sin(g.yaw);
  const double ct = std::cos(g.pitch), st = std::sin(g.pitch);
  const Point3 a = {cp * w.x + sp * w.z, w.y, -sp * w.x + cp * w.z};  // R_y(phi)
  return {a.x, ct * a.y - st * a.z, st * a.y + ct * a.z};             // R_x(theta)
}

CorridorGeometry TestGeometry() {
  CorridorGeometry g;
  g.yaw = 0.12;
  g.pitch = 0.07;
  g.width = 2.4;
  g.offset = 0.3;  // d_l = 1.5, d_r = 0.9.
  g.camera_height = 0.7;
  g.ceiling_height = 2.6;
  g.end_distance = 25.0;
  return g;
}

const visualization_msgs::Marker* Find(const visualization_msgs::MarkerArray& array, int id) {
  for (const auto& m : array.markers) {
    if (m.id == id) return &m;
  }
  return nullptr;
}

// The marker's six points are the quad's corners (c0, c1, c2, c0, c2, c3) in some rotation of
// c0..c3; checks that its corner set equals `corners` (in the camera frame).
void ExpectQuad(const visualization_msgs::Marker* marker, const std::vector<Point3>& corners,
                const char* what) {
  ASSERT_NE(marker, nullptr) << what;
  EXPECT_EQ(marker->action, visualization_msgs::Marker::ADD) << what;
  EXPECT_EQ(marker->type, visualization_msgs::Marker::TRIANGLE_LIST) << what;
  ASSERT_EQ(marker->points.size(), 6u) << what;
  EXPECT_EQ(marker->header.frame_id, "cam_optical");
  // Triangle order: points 3 and 0 are c0, points 5 and 2 are c2.
  const auto& p = marker->points;
  EXPECT_EQ(p[0], p[3]) << what;
  EXPECT_EQ(p[2], p[4]) << what;
  const std::vector<geometry_msgs::Point> quad = {p[0], p[1], p[2], p[5]};
  for (const Point3& c : corners) {
    bool found = false;
    for (const auto& q : quad) {
      if (std::abs(q.x - c.x) < 1e-9 && std::abs(q.y - c.y) < 1e-9 && std::abs(q.z - c.z) < 1e-9) {
        found = true;
      }
    }
    EXPECT_TRUE(found) << what << ": corner (" << c.x << ", " << c.y << ", " << c.z
                       << ") missing";
  }
}

TEST(CorridorMarkersTest, CornersOfEverySurface) {
  const CorridorGeometry g = TestGeometry();
  std_msgs::Header header;
  header.frame_id = "cam_optical";
  const double max_range = 40, max_height = 2.5;
  const auto array = CorridorMarkers(g, max_range, max_height, header);
  const double h = 0.7, top = 0.7 - 2.6, left = -1.5, right = 0.9, end = 25.0;
  const auto c = [&](double x, double y, double z) { return ToCamera(g, {x, y, z}); };
  ExpectQuad(Find(array, 0), {c(left, h, 0), c(right, h, 0), c(right, h, end), c(left, h, end)},
             "floor");
  ExpectQuad(Find(array, 1), {c(left, h, 0), c(left, h, end), c(left, top, end), c(left, top, 0)},
             "left wall");
  ExpectQuad(Find(array, 2),
             {c(right, h, 0), c(right, h, end), c(right, top, end), c(right, top, 0)},
             "right wall");
  ExpectQuad(Find(array, 3),
             {c(left, top, 0), c(left, top, end), c(right, top, end), c(right, top, 0)},
             "ceiling");
  ExpectQuad(Find(array, 4),
             {c(left, h, end), c(right, h, end), c(right, top, end), c(left, top, end)},
             "end wall");

  // Plane equations in the camera frame (geometry.md section 2): n.P = h on the floor,
  // m.P = -d_l and +d_r on the walls.
  const double n[3] = {0, std::cos(g.pitch), std::sin(g.pitch)};
  const double m[3] = {std::cos(g.yaw), std::sin(g.pitch) * std::sin(g.yaw),
                       -std::cos(g.pitch) * std::sin(g.yaw)};
  for (const auto& p : Find(array, 0)->points) {
    EXPECT_NEAR(n[0] * p.x + n[1] * p.y + n[2] * p.z, g.camera_height, 1e-9);
  }
  for (const auto& p : Find(array, 1)->points) {
    EXPECT_NEAR(m[0] * p.x + m[1] * p.y + m[2] * p.z, -g.LeftDistance(), 1e-9);
  }
  for (const auto& p : Find(array, 2)->points) {
    EXPECT_NEAR(m[0] * p.x + m[1] * p.y + m[2] * p.z, g.RightDistance(), 1e-9);
  }
  for (const auto& p : Find(array, 3)->points) {
    EXPECT_NEAR(n[0] * p.x + n[1] * p.y + n[2] * p.z, g.camera_height - g.ceiling_height, 1e-9);
  }
}

// A frame recovered level from a roll of 90 degrees, with no pitch or yaw: the floor (camera
// y = h without roll) is turned by R_z(90 deg), (x, y) -> (-y, x), to camera x = -h.
TEST(CorridorMarkersTest, ARolledFramesSurfacesAreTurnedIntoItsCamera) {
  CorridorGeometry g = TestGeometry();
  g.pitch = g.yaw = 0;
  std_msgs::Header header;
  header.frame_id = "cam_optical";
  const auto array = CorridorMarkers(g, 30.0, 2.0, header, M_PI / 2);
  ASSERT_NE(Find(array, 0), nullptr);
  for (const auto& p : Find(array, 0)->points) EXPECT_NEAR(p.x, -g.camera_height, 1e-9);
}

// Without a ceiling or an end wall: walls up to max_height, out to max_range, and DELETEs.
TEST(CorridorMarkersTest, NoCeilingNoEndWall) {
  CorridorGeometry g = TestGeometry();
  g.ceiling_height = 0;
  g.end_distance = 0;
  std_msgs::Header header;
  header.frame_id = "cam_optical";
  const auto array = CorridorMarkers(g, 30.0, 2.0, header);
  const double h = 0.7, top = 0.7 - 2.0, left = -1.5, end = 30.0;
  const auto c = [&](double x, double y, double z) { return ToCamera(g, {x, y, z}); };
  ExpectQuad(Find(array, 1), {c(left, h, 0), c(left, h, end), c(left, top, end), c(left, top, 0)},
             "left wall");
  for (int id : {3, 4}) {
    ASSERT_NE(Find(array, id), nullptr);
    EXPECT_EQ(Find(array, id)->action, visualization_msgs::Marker::DELETE) << id;
  }
  const auto cleared = ClearCorridorMarkers(header);
  ASSERT_EQ(cleared.markers.size(), 1u);
  EXPECT_EQ(cleared.markers[0].action, visualization_msgs::Marker::DELETEALL);
}

}  // namespace
}  // namespace corridor
