// EXIF orientation: a JPEG whose APP1 block says how the camera was turned is read upright on
// request (as photo viewers show it) and as stored otherwise; the tag is found in both byte orders.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "io/exif_orientation.h"
#include "corridor_depth/image_io.h"
#include "tests/io/test_dir.h"

namespace corridor {
namespace {

// An APP1 EXIF block with one IFD0 entry, the orientation tag, written byte by byte.
std::string ExifBlock(int orientation, bool little) {
  const auto u16 = [little](int v) {
    const char hi = static_cast<char>((v >> 8) & 0xFF), lo = static_cast<char>(v & 0xFF);
    return little ? std::string{lo, hi} : std::string{hi, lo};
  };
  const auto u32 = [little, &u16](int v) {
    return little ? u16(v & 0xFFFF) + u16(v >> 16) : u16(v >> 16) + u16(v & 0xFFFF);
  };
  std::string tiff = little ? "II" : "MM";
  tiff += u16(42) + u32(8);               // Header; IFD0 right after it.
  tiff += u16(1);                         // One entry:
  tiff += u16(0x0112) + u16(3) + u32(1);  // orientation, SHORT, one value,
  tiff += u16(orientation) + u16(0);      // the value, padded to four bytes;
  tiff += u32(0);                         // no next IFD.
  const std::string payload = std::string("Exif\0\0", 6) + tiff;
  const int length = static_cast<int>(payload.size()) + 2;
  return std::string{static_cast<char>(0xFF), static_cast<char>(0xE1),
                     static_cast<char>(length >> 8), static_cast<char>(length & 0xFF)} +
         payload;
}

// A small asymmetric picture: a bright block in the top-left corner of a dark image.
cv::Mat Picture() {
  cv::Mat image(40, 64, CV_8UC3, cv::Scalar(30, 30, 30));
  image(cv::Rect(2, 2, 20, 10)).setTo(cv::Scalar(240, 240, 240));
  return image;
}

// The picture as a JPEG with the EXIF block inserted after the start-of-image marker.
std::string JpegWithOrientation(int orientation, bool little) {
  std::vector<uchar> encoded;
  cv::imencode(".jpg", Picture(), encoded, {cv::IMWRITE_JPEG_QUALITY, 100});
  const std::string jpeg(encoded.begin(), encoded.end());
  return jpeg.substr(0, 2) + ExifBlock(orientation, little) + jpeg.substr(2);
}

// Where the bright block's centre lies in an image.
cv::Point2d BrightCentre(const cv::Mat& bgr) {
  cv::Mat grey;
  cv::cvtColor(bgr, grey, cv::COLOR_BGR2GRAY);
  const cv::Moments m = cv::moments(grey > 128, true);
  return {m.m10 / m.m00, m.m01 / m.m00};
}

TEST(ExifOrientation, ReadsTheTagInBothByteOrders) {
  for (const bool little : {true, false}) {
    for (int orientation = 1; orientation <= 8; ++orientation) {
      EXPECT_EQ(ExifOrientation(JpegWithOrientation(orientation, little)), orientation);
    }
  }
  std::vector<uchar> plain;
  cv::imencode(".jpg", Picture(), plain);
  EXPECT_EQ(ExifOrientation(std::string(plain.begin(), plain.end())), 1);
  EXPECT_EQ(ExifOrientation("not a jpeg"), 1);
  // A block cut short reads as no tag, not past its end.
  const std::string cut = JpegWithOrientation(6, true).substr(0, 20);
  EXPECT_EQ(ExifOrientation(cut), 1);
}

TEST(ExifOrientation, APhotoTurnedAQuarterIsReadUpright) {
  testing_util::TestDir dir;
  dir.Write("turned.jpg", JpegWithOrientation(6, true));
  cv::Mat stored, upright;
  ASSERT_TRUE(ReadColorImage(dir.Path("turned.jpg"), &stored).ok());
  ASSERT_TRUE(ReadColorImage(dir.Path("turned.jpg"), &upright, ImageOrientation::kUpright).ok());
  EXPECT_EQ(stored.size(), cv::Size(64, 40));
  ASSERT_EQ(upright.size(), cv::Size(40, 64));
  // Orientation 6: the stored picture turned a quarter clockwise. The block, centred at
  // (11.5, 6.5) of 64x40 as stored, goes to (40 - 1 - 6.5, 11.5) upright.
  const cv::Point2d as_stored = BrightCentre(stored), turned = BrightCentre(upright);
  EXPECT_NEAR(as_stored.x, 11.5, 1.0);
  EXPECT_NEAR(as_stored.y, 6.5, 1.0);
  EXPECT_NEAR(turned.x, 39 - 6.5, 1.0);
  EXPECT_NEAR(turned.y, 11.5, 1.0);
}

TEST(ExifOrientation, EveryOrientationPutsTheBlockTopLeftAgain) {
  // A camera turned as each tag says stored the scene so that turning it back puts the block
  // where Picture() drew it: this test stores each such view and reads it upright.
  const cv::Mat scene = Picture();
  const std::vector<std::pair<int, cv::Mat>> stored_views = [&] {
    std::vector<std::pair<int, cv::Mat>> views;
    cv::Mat v;
    cv::flip(scene, v, 1), views.push_back({2, v.clone()});
    cv::rotate(scene, v, cv::ROTATE_180), views.push_back({3, v.clone()});
    cv::flip(scene, v, 0), views.push_back({4, v.clone()});
    cv::transpose(scene, v), views.push_back({5, v.clone()});
    cv::rotate(scene, v, cv::ROTATE_90_COUNTERCLOCKWISE), views.push_back({6, v.clone()});
    cv::transpose(scene, v), cv::flip(v, v, -1), views.push_back({7, v.clone()});
    cv::rotate(scene, v, cv::ROTATE_90_CLOCKWISE), views.push_back({8, v.clone()});
    return views;
  }();
  for (const auto& [orientation, view] : stored_views) {
    cv::Mat upright = view.clone();
    ApplyExifOrientation(orientation, &upright);
    ASSERT_EQ(upright.size(), scene.size()) << orientation;
    EXPECT_EQ(cv::norm(upright, scene, cv::NORM_INF), 0) << "orientation " << orientation;
  }
}

}  // namespace
}  // namespace corridor
