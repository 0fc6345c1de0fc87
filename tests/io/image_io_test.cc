#include "corridor_depth/image_io.h"

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "tests/io/test_dir.h"

namespace corridor {
namespace {

using testing_util::Contains;
using testing_util::ReadAll;
using testing_util::TestDir;

// A deterministic 8-bit BGR test pattern (noise-like, so compressed files are not tiny).
cv::Mat Pattern(int rows, int cols) {
  cv::Mat m(rows, cols, CV_8UC3);
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c) {
      m.at<cv::Vec3b>(r, c) = cv::Vec3b(static_cast<uint8_t>((r * 37 + c * 11) % 256),
                                        static_cast<uint8_t>((r * 5 + c * 91) % 256),
                                        static_cast<uint8_t>((r * c * 13) % 256));
    }
  }
  return m;
}

// Writes `image` with plain cv::imwrite (independent of the code under test).
std::string Imwrite(const TestDir& dir, const std::string& name, const cv::Mat& image) {
  const std::string path = dir.Path(name);
  EXPECT_TRUE(cv::imwrite(path, image));
  return path;
}

// Expects ReadColorImage to fail with `code`, naming the path and containing `part`.
void ExpectReadError(const std::string& path, StatusCode code, const std::string& part) {
  cv::Mat bgr;
  const Status status = ReadColorImage(path, &bgr);
  EXPECT_EQ(status.code(), code) << status.ToString();
  EXPECT_TRUE(Contains(status.message(), path)) << status.message();
  EXPECT_TRUE(Contains(status.message(), part)) << status.message();
}

TEST(ImageIoTest, MissingEmptyAndTextFilesAreErrors) {
  TestDir dir;
  ExpectReadError(dir.Path("missing.png"), StatusCode::kNotFound, "no such file");
  ExpectReadError(dir.Write("empty.png", ""), StatusCode::kIoError, "empty");
  ExpectReadError(dir.Write("text.png", "this is not a picture\n"), StatusCode::kIoError,
                  "not a readable image");
  ExpectReadError(dir.root().string(), StatusCode::kInvalidArgument, "folder");
}

TEST(ImageIoTest, TruncatedPngIsAnError) {
  TestDir dir;
  const std::string full = ReadAll(Imwrite(dir, "full.png", Pattern(32, 32)));
  ASSERT_GT(full.size(), 100u);
  ExpectReadError(dir.Write("half.png", full.substr(0, full.size() / 2)), StatusCode::kIoError,
                  "truncated PNG");
  // Only the 12-byte IEND chunk missing: decoders may still return the pixels.
  ExpectReadError(dir.Write("no_iend.png", full.substr(0, full.size() - 12)),
                  StatusCode::kIoError, "truncated PNG");
}

TEST(ImageIoTest, TruncatedJpegIsAnError) {
  TestDir dir;
  const std::string full = ReadAll(Imwrite(dir, "full.jpg", Pattern(64, 64)));
  ASSERT_GT(full.size(), 200u);
  ExpectReadError(dir.Write("half.jpg", full.substr(0, full.size() / 2)), StatusCode::kIoError,
                  "truncated JPEG");
  // Only the end-of-image marker FFD9 missing: libjpeg would return the full image with a warning.
  ExpectReadError(dir.Write("no_eoi.jpg", full.substr(0, full.size() - 2)), StatusCode::kIoError,
                  "truncated JPEG");
  cv::Mat bgr;
  ASSERT_TRUE(ReadColorImage(dir.Path("full.jpg"), &bgr).ok());
  EXPECT_EQ(bgr.type(), CV_8UC3);
  EXPECT_EQ(bgr.size(), cv::Size(64, 64));
}

TEST(ImageIoTest, EveryPrefixOfAnImageIsRejected) {
  TestDir dir;
  for (const char* name : {"p.png", "p.jpg"}) {
    const std::string full = ReadAll(Imwrite(dir, name, Pattern(16, 16)));
    const std::string cut = dir.Path(std::string("cut_") + name);
    for (size_t n = 0; n < full.size(); n += 7) {
      dir.Write(std::string("cut_") + name, full.substr(0, n));
      cv::Mat bgr;
      EXPECT_FALSE(ReadColorImage(cut, &bgr).ok()) << name << " cut to " << n << " bytes";
    }
  }
}

TEST(ImageIoTest, ColourPngRoundTripsExactly) {
  TestDir dir;
  const cv::Mat image = Pattern(5, 7);
  const std::string path = dir.Path("deep/er/colour.png");
  ASSERT_TRUE(WriteImageAtomic(path, image).ok());
  cv::Mat bgr;
  ASSERT_TRUE(ReadColorImage(path, &bgr).ok());
  ASSERT_EQ(bgr.type(), CV_8UC3);
  EXPECT_EQ(cv::norm(bgr, image, cv::NORM_INF), 0.0);
  // Nothing but the final file is left in the folder.
  int entries = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir.Path("deep/er"))) {
    EXPECT_EQ(e.path().filename(), "colour.png");
    ++entries;
  }
  EXPECT_EQ(entries, 1);
}

TEST(ImageIoTest, SixteenBitColourIsScaledTo8Bit) {
  TestDir dir;
  cv::Mat image(1, 2, CV_16UC3);
  image.at<cv::Vec3w>(0, 0) = cv::Vec3w(2570, 5140, 7710);  // 257 * (10, 20, 30).
  image.at<cv::Vec3w>(0, 1) = cv::Vec3w(65535, 0, 1000);    // 255, 0, 1000/257 = 3.89 -> 4.
  cv::Mat bgr;
  ASSERT_TRUE(ReadColorImage(Imwrite(dir, "deep.png", image), &bgr).ok());
  ASSERT_EQ(bgr.type(), CV_8UC3);
  EXPECT_EQ(bgr.at<cv::Vec3b>(0, 0), cv::Vec3b(10, 20, 30));
  EXPECT_EQ(bgr.at<cv::Vec3b>(0, 1), cv::Vec3b(255, 0, 4));
}

TEST(ImageIoTest, SixteenBitGreyIsScaledAndExpanded) {
  TestDir dir;
  cv::Mat image(1, 2, CV_16UC1);
  image.at<uint16_t>(0, 0) = 514;    // 514 / 257 = 2.
  image.at<uint16_t>(0, 1) = 65535;  // 255.
  cv::Mat bgr;
  ASSERT_TRUE(ReadColorImage(Imwrite(dir, "grey16.png", image), &bgr).ok());
  ASSERT_EQ(bgr.type(), CV_8UC3);
  EXPECT_EQ(bgr.at<cv::Vec3b>(0, 0), cv::Vec3b(2, 2, 2));
  EXPECT_EQ(bgr.at<cv::Vec3b>(0, 1), cv::Vec3b(255, 255, 255));
}

TEST(ImageIoTest, AlphaIsDropped) {
  TestDir dir;
  cv::Mat image(1, 2, CV_8UC4);
  image.at<cv::Vec4b>(0, 0) = cv::Vec4b(1, 2, 3, 4);
  image.at<cv::Vec4b>(0, 1) = cv::Vec4b(200, 100, 50, 0);  // Fully transparent: colour kept.
  cv::Mat bgr;
  ASSERT_TRUE(ReadColorImage(Imwrite(dir, "alpha.png", image), &bgr).ok());
  ASSERT_EQ(bgr.type(), CV_8UC3);
  EXPECT_EQ(bgr.at<cv::Vec3b>(0, 0), cv::Vec3b(1, 2, 3));
  EXPECT_EQ(bgr.at<cv::Vec3b>(0, 1), cv::Vec3b(200, 100, 50));
}

TEST(ImageIoTest, GreyIsExpandedToBgr) {
  TestDir dir;
  cv::Mat image(2, 1, CV_8UC1);
  image.at<uint8_t>(0, 0) = 77;
  image.at<uint8_t>(1, 0) = 0;
  cv::Mat bgr;
  ASSERT_TRUE(ReadColorImage(Imwrite(dir, "grey.png", image), &bgr).ok());
  ASSERT_EQ(bgr.type(), CV_8UC3);
  EXPECT_EQ(bgr.at<cv::Vec3b>(0, 0), cv::Vec3b(77, 77, 77));
  EXPECT_EQ(bgr.at<cv::Vec3b>(1, 0), cv::Vec3b(0, 0, 0));
}

TEST(ImageIoTest, ReadsMillimetreDepth) {
  TestDir dir;
  cv::Mat mm(1, 3, CV_16UC1);
  mm.at<uint16_t>(0, 0) = 0;
  mm.at<uint16_t>(0, 1) = 1234;
  mm.at<uint16_t>(0, 2) = 65535;
  cv::Mat depth;
  ASSERT_TRUE(ReadDepthPng(Imwrite(dir, "depth.png", mm), &depth).ok());
  ASSERT_EQ(depth.type(), CV_32FC1);
  EXPECT_EQ(depth.at<float>(0, 0), 0.0f);
  EXPECT_FLOAT_EQ(depth.at<float>(0, 1), 1.234f);
  EXPECT_FLOAT_EQ(depth.at<float>(0, 2), 65.535f);
}

TEST(ImageIoTest, DepthMustBeSixteenBitSingleChannel) {
  TestDir dir;
  cv::Mat depth;
  const std::string grey = Imwrite(dir, "grey.png", cv::Mat(2, 2, CV_8UC1, cv::Scalar(3)));
  Status status = ReadDepthPng(grey, &depth);
  EXPECT_EQ(status.code(), StatusCode::kInvalidArgument);
  EXPECT_TRUE(Contains(status.message(), grey) && Contains(status.message(), "8UC1"))
      << status.message();
  const std::string colour = Imwrite(dir, "colour.png", Pattern(2, 2));
  status = ReadDepthPng(colour, &depth);
  EXPECT_TRUE(Contains(status.message(), "8UC3")) << status.message();
  status = ReadDepthPng(dir.Path("missing.png"), &depth);
  EXPECT_EQ(status.code(), StatusCode::kNotFound);
}

TEST(ImageIoTest, WritesDepthRoundedClampedAndZeroed) {
  TestDir dir;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  // Expected mm, by hand: 1000.4 -> 1000, 1000.6 -> 1001, 0 -> 0, -1 -> 0, NaN -> 0, inf -> 0,
  // 70000 -> 65535, 0.4 mm -> 0.
  const float metres[8] = {1.0004f, 1.0006f, 0.0f, -1.0f, nan, inf, 70.0f, 0.0004f};
  const uint16_t expected[8] = {1000, 1001, 0, 0, 0, 0, 65535, 0};
  const cv::Mat depth(2, 4, CV_32FC1, const_cast<float*>(metres));
  const std::string path = dir.Path("d/depth.png");
  ASSERT_TRUE(WriteDepthPng(path, depth).ok());
  const cv::Mat mm = cv::imread(path, cv::IMREAD_UNCHANGED);
  ASSERT_EQ(mm.type(), CV_16UC1);
  for (int i = 0; i < 8; ++i) EXPECT_EQ(mm.at<uint16_t>(i / 4, i % 4), expected[i]) << i;
}

TEST(ImageIoTest, WriteDepthRejectsBadInput) {
  TestDir dir;
  EXPECT_EQ(WriteDepthPng(dir.Path("a.png"), cv::Mat(2, 2, CV_64FC1, cv::Scalar(1))).code(),
            StatusCode::kInvalidArgument);
  EXPECT_EQ(WriteDepthPng(dir.Path("a.png"), cv::Mat()).code(), StatusCode::kInvalidArgument);
  const Status status = WriteDepthPng(dir.Path("a.jpg"), cv::Mat(2, 2, CV_32FC1, cv::Scalar(1)));
  EXPECT_TRUE(Contains(status.message(), ".png")) << status.message();
  EXPECT_FALSE(std::filesystem::exists(dir.Path("a.png")));
}

TEST(ImageIoTest, WriteImageRejectsBadInput) {
  TestDir dir;
  EXPECT_EQ(WriteImageAtomic(dir.Path("a.png"), cv::Mat()).code(), StatusCode::kInvalidArgument);
  Status status = WriteImageAtomic(dir.Path("a.xyz"), Pattern(2, 2));
  EXPECT_EQ(status.code(), StatusCode::kInvalidArgument);
  EXPECT_TRUE(Contains(status.message(), ".xyz")) << status.message();
  EXPECT_EQ(WriteImageAtomic(dir.Path("noext"), Pattern(2, 2)).code(),
            StatusCode::kInvalidArgument);
  dir.Write("file", "x");
  status = WriteImageAtomic(dir.Path("file/a.png"), Pattern(2, 2));  // Parent is a file.
  EXPECT_EQ(status.code(), StatusCode::kIoError);
}

TEST(ImageIoTest, WritesTextAtomically) {
  TestDir dir;
  const std::string path = dir.Path("x/y/notes.txt");
  ASSERT_TRUE(WriteTextAtomic(path, "first\n").ok());
  ASSERT_TRUE(WriteTextAtomic(path, "second\n").ok());
  EXPECT_EQ(ReadAll(path), "second\n");
  int entries = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir.Path("x/y"))) {
    EXPECT_EQ(e.path().filename(), "notes.txt");
    ++entries;
  }
  EXPECT_EQ(entries, 1);
}

}  // namespace
}  // namespace corridor
