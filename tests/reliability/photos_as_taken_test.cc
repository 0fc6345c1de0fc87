// Photos as people take them: a folder of photos of different sizes with --hfov gives each photo
// the result it gets alone (each its own camera, each frame on its own); a photo stored sideways
// with an EXIF orientation tag gives the upright photo's result; a second run into the same
// output folder keeps the first run's rows, and an older geometry.csv is migrated, never lost.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "io/csv_row.h"
#include "tests/reliability/reliability_util.h"

namespace corridor {
namespace {

using testing_util::Contains;
using testing_util::ExpectCleanExit;
using testing_util::ReadAll;
using testing_util::ReliabilityCamera;
using testing_util::ReliabilityGeometry;
using testing_util::RunDepthTool;
using testing_util::ScratchDir;

// geometry.csv as rows of named fields, by frame.
std::map<std::string, std::map<std::string, std::string>> ReadRows(const std::string& path) {
  std::map<std::string, std::map<std::string, std::string>> rows;
  std::istringstream in(ReadAll(path));
  std::string line;
  std::vector<std::string> header, fields;
  while (std::getline(in, line)) {
    if (header.empty()) {
      SplitCsvRow(line, &header);
      continue;
    }
    SplitCsvRow(line, &fields);
    if (fields.size() != header.size()) {
      ADD_FAILURE() << "row of " << fields.size() << " fields: " << line;
      continue;
    }
    for (size_t i = 0; i < header.size(); ++i) rows[fields[0]][header[i]] = fields[i];
  }
  return rows;
}

double Number(const std::string& text) { return std::stod(text); }

// A corridor seen by a pinhole of `hfov_deg` at the given size (the test renderer's own camera).
cv::Mat Photo(int width, int height, double hfov_deg, const CorridorGeometry& g, int seed) {
  const Camera camera =
      Camera::FromHorizontalFov(width, height, hfov_deg * M_PI / 180, g.camera_height);
  return testing_util::RenderTestCorridor(camera, g, seed);
}

TEST(PhotosAsTaken, EachPhotoOfAFolderGetsTheResultItGetsAlone) {
  ScratchDir dir;
  const double hfov = 70;
  dir.WriteImage("in/a_small.png", Photo(320, 240, hfov, ReliabilityGeometry(0.05, 0.08, 0.1), 1));
  dir.WriteImage("in/b_large.png",
                 Photo(480, 360, hfov, ReliabilityGeometry(-0.08, 0.05, -0.15, 2.6), 2));
  dir.WriteImage("alone/b_large.png",
                 Photo(480, 360, hfov, ReliabilityGeometry(-0.08, 0.05, -0.15, 2.6), 2));
  const std::vector<std::string> flags = {"--hfov=70", "--camera_height=1.2"};
  ExpectCleanExit(RunDepthTool(dir.Path("in"), dir.Path("out"), dir, flags), 0, {});
  ExpectCleanExit(RunDepthTool(dir.Path("alone/b_large.png"), dir.Path("out1"), dir, flags), 0, {});
  const auto folder = ReadRows(dir.Path("out/in/geometry.csv"));
  const auto alone = ReadRows(dir.Path("out1/alone/geometry.csv"));
  ASSERT_EQ(folder.size(), 2u);
  ASSERT_EQ(alone.count("b_large"), 1u);
  // Each photo's camera from its own size: fx = (w / 2) / tan(hfov / 2), centre (w - 1) / 2.
  const double t = std::tan(0.5 * hfov * M_PI / 180);
  EXPECT_NEAR(Number(folder.at("a_small").at("fx_px")), 160 / t, 1e-3);
  EXPECT_NEAR(Number(folder.at("b_large").at("fx_px")), 240 / t, 1e-3);
  EXPECT_NEAR(Number(folder.at("b_large").at("cx_px")), 239.5, 1e-3);
  EXPECT_NEAR(Number(folder.at("b_large").at("cy_px")), 179.5, 1e-3);
  for (const char* column : {"status", "yaw_rad", "pitch_rad", "offset_m", "width_m"}) {
    EXPECT_EQ(folder.at("b_large").at(column), alone.at("b_large").at(column)) << column;
  }
  EXPECT_EQ(folder.at("a_small").at("status"), "ok");
  EXPECT_NEAR(Number(folder.at("b_large").at("width_m")), 2.6, 0.05);
  EXPECT_NEAR(Number(folder.at("a_small").at("width_m")), 2.1, 0.05);
}

TEST(PhotosAsTaken, APhotoStoredSidewaysIsReadUpright) {
  ScratchDir dir;
  const cv::Mat upright = Photo(480, 360, 65, ReliabilityGeometry(0.04, 0.07, 0.12, 2.3), 3);
  // The same photo as a phone stores it when held sideways: turned a quarter counter-clockwise,
  // with EXIF orientation 6 (turn it a quarter clockwise to show it).
  cv::Mat stored;
  cv::rotate(upright, stored, cv::ROTATE_90_COUNTERCLOCKWISE);
  std::vector<uchar> jpeg;
  cv::imencode(".jpg", stored, jpeg, {cv::IMWRITE_JPEG_QUALITY, 98});
  const std::string tiff = std::string("II*\0\x08\0\0\0", 8) + std::string("\x01\0", 2) +
                           std::string("\x12\x01\x03\0\x01\0\0\0\x06\0\0\0", 12) +
                           std::string("\0\0\0\0", 4);
  const std::string payload = std::string("Exif\0\0", 6) + tiff;
  const int length = static_cast<int>(payload.size()) + 2;
  const std::string app1 = std::string{'\xFF', '\xE1', static_cast<char>(length >> 8),
                                       static_cast<char>(length & 0xFF)} +
                           payload;
  const std::string bytes(jpeg.begin(), jpeg.end());
  dir.Write("turned/photo.jpg", bytes.substr(0, 2) + app1 + bytes.substr(2));
  std::vector<uchar> plain;
  cv::imencode(".jpg", upright, plain, {cv::IMWRITE_JPEG_QUALITY, 98});
  dir.Write("upright/photo.jpg", std::string(plain.begin(), plain.end()));
  const std::vector<std::string> flags = {"--hfov=65", "--camera_height=1.2"};
  ExpectCleanExit(RunDepthTool(dir.Path("turned/photo.jpg"), dir.Path("out_t"), dir, flags), 0, {});
  ExpectCleanExit(RunDepthTool(dir.Path("upright/photo.jpg"), dir.Path("out_u"), dir, flags), 0,
                  {});
  const auto turned = ReadRows(dir.Path("out_t/turned/geometry.csv")).at("photo");
  const auto straight = ReadRows(dir.Path("out_u/upright/geometry.csv")).at("photo");
  EXPECT_EQ(turned.at("fx_px"), straight.at("fx_px"));  // Sized as 480x360, not 360x480.
  // The two JPEGs compress different pixels: the geometry agrees to compression noise.
  EXPECT_NEAR(Number(turned.at("width_m")), Number(straight.at("width_m")), 0.01);
  EXPECT_NEAR(Number(turned.at("yaw_rad")), Number(straight.at("yaw_rad")), 0.005);
  EXPECT_NEAR(Number(turned.at("width_m")), 2.3, 0.05);
}

TEST(PhotosAsTaken, ASecondRunKeepsTheFirstRunsRows) {
  ScratchDir dir;
  const Camera camera = ReliabilityCamera();
  dir.WriteCamera("in/camera.yaml", camera);
  const cv::Mat a = testing_util::RenderTestCorridor(camera, ReliabilityGeometry(), 1);
  const cv::Mat b =
      testing_util::RenderTestCorridor(camera, ReliabilityGeometry(-0.1, 0.06, -0.2), 2);
  dir.WriteImage("in/001.png", a);
  dir.WriteImage("in/002.png", b);
  ExpectCleanExit(RunDepthTool(dir.Path("in"), dir.Path("out"), dir), 0, {});
  const auto first = ReadRows(dir.Path("out/in/geometry.csv"));
  ASSERT_EQ(first.size(), 2u);
  // Other photos of the same folder: the first run's rows stay.
  std::filesystem::remove(dir.Path("in/001.png"));
  std::filesystem::remove(dir.Path("in/002.png"));
  dir.WriteImage("in/003.png", a);
  ExpectCleanExit(RunDepthTool(dir.Path("in"), dir.Path("out"), dir), 0, {});
  auto second = ReadRows(dir.Path("out/in/geometry.csv"));
  ASSERT_EQ(second.size(), 3u);
  EXPECT_EQ(second.at("001"), first.at("001"));
  EXPECT_EQ(second.at("002"), first.at("002"));
  EXPECT_EQ(second.at("003").at("status"), "ok");
  // A frame computed again replaces its own row: still one row for it.
  dir.WriteImage("in/001.png", b);
  ExpectCleanExit(RunDepthTool(dir.Path("in"), dir.Path("out"), dir), 0, {});
  const std::string text = ReadAll(dir.Path("out/in/geometry.csv"));
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 4) << text;
  const auto third = ReadRows(dir.Path("out/in/geometry.csv"));
  EXPECT_EQ(third.at("001").at("width_m"), first.at("002").at("width_m"));
}

TEST(PhotosAsTaken, AnOlderGeometryCsvIsMigrated) {
  ScratchDir dir;
  const Camera camera = ReliabilityCamera();
  dir.WriteCamera("in/camera.yaml", camera);
  dir.WriteImage("in/new.png", testing_util::RenderTestCorridor(camera, ReliabilityGeometry(), 1));
  dir.Write("out/in/geometry.csv",
            "frame,status,yaw,pitch,offset,width,ceiling_height,end_distance,seconds,stamp\n"
            "old1,ok: width held,0.010000,0.020000,0.1000,2.2000,2.7,,0.002,\n"
            "old2,no corridor found: only the left junction is visible,,,,,,,,\n");
  ExpectCleanExit(RunDepthTool(dir.Path("in"), dir.Path("out"), dir), 0, {});
  const std::string text = ReadAll(dir.Path("out/in/geometry.csv"));
  EXPECT_EQ(
      text.rfind("frame,status,note,confidence,yaw_rad,pitch_rad,roll_rad,offset_m,width_m,", 0),
      0u)
      << text;
  const auto rows = ReadRows(dir.Path("out/in/geometry.csv"));
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows.at("old1").at("status"), "ok");
  EXPECT_EQ(rows.at("old1").at("note"), "width held");
  EXPECT_EQ(rows.at("old1").at("width_m"), "2.2000");
  EXPECT_EQ(rows.at("old2").at("status"), "refused");
  EXPECT_EQ(rows.at("old2").at("note"), "no_corridor_found: only the left junction is visible");
  EXPECT_EQ(rows.at("new").at("status"), "ok");
  // A file from before the roll column: its rows gain an empty roll_rad, their values kept.
  dir.Write("out/in/geometry.csv",
            "frame,status,note,confidence,yaw_rad,pitch_rad,offset_m,width_m,ceiling_height_m,"
            "end_distance_m,fx_px,fy_px,cx_px,cy_px,time_s,stamp\n"
            "old3,ok,,0.900,0.010000,0.020000,0.1000,2.2000,2.7000,,400.000,400.000,320.000,"
            "240.000,0.002000,\n");
  ExpectCleanExit(RunDepthTool(dir.Path("in"), dir.Path("out"), dir), 0, {});
  const auto migrated = ReadRows(dir.Path("out/in/geometry.csv"));
  ASSERT_EQ(migrated.count("old3"), 1u);
  EXPECT_EQ(migrated.at("old3").at("roll_rad"), "");
  EXPECT_EQ(migrated.at("old3").at("offset_m"), "0.1000");
  EXPECT_EQ(migrated.at("old3").at("width_m"), "2.2000");
  EXPECT_EQ(migrated.at("old3").at("time_s"), "0.002000");
  EXPECT_EQ(migrated.at("new").at("roll_rad"), "0.000000");
  // A file that is no geometry.csv is left as it is, with a clear error.
  dir.Write("out/in/geometry.csv", "a,b,c\n1,2,3\n");
  ExpectCleanExit(RunDepthTool(dir.Path("in"), dir.Path("out"), dir), 2,
                  {dir.Path("out/in/geometry.csv"), "header", "left as it is"});
  EXPECT_EQ(ReadAll(dir.Path("out/in/geometry.csv")), "a,b,c\n1,2,3\n");
}

}  // namespace
}  // namespace corridor
