// Where the junction search's working pixels lie in the image (MakeJunctionSearchRegion and its
// coordinate maps): crop rows and scales worked out by hand, and a bright row found again after
// the halvings.

#include "perception/junction_search_region.h"

#include <gtest/gtest.h>

#include <vector>

#include <opencv2/core.hpp>

#include "perception/working_image.h"

namespace corridor {
namespace {

TEST(JunctionSearchRegionTest, AnImageThatFitsIsSearchedAsItIs) {
  const cv::Mat color(480, 640, CV_8UC3, cv::Scalar(90, 90, 90));
  JunctionSearchRegion region;
  ASSERT_TRUE(MakeJunctionSearchRegion(color, nullptr, 240, 640, &region).ok());
  EXPECT_EQ(region.scale, 1);
  EXPECT_EQ(region.crop_top, 0);
  EXPECT_EQ(region.work_roi_top, 240);
  EXPECT_EQ(region.work.data, color.data);  // Not copied.
  EXPECT_EQ(region.work.size(), color.size());
  const GradientGrid grid = SearchRegionGrid(region);
  EXPECT_EQ(grid.scale, 1);
  EXPECT_EQ(grid.first_row, 240);
}

TEST(JunctionSearchRegionTest, AWideImageIsCroppedAboveTheRegionAndHalved) {
  // 1280 px wide, max 640: halved once. The crop starts 4 working rows (8 image rows) above
  // row 480, at 472; the region's top is working row (480 - 472) / 2 = 4.
  const cv::Mat color(960, 1280, CV_8UC3, cv::Scalar(90, 90, 90));
  JunctionSearchRegion region;
  ASSERT_TRUE(MakeJunctionSearchRegion(color, nullptr, 480, 640, &region).ok());
  EXPECT_EQ(region.scale, 2);
  EXPECT_EQ(region.crop_top, 472);
  EXPECT_EQ(region.work_roi_top, 4);
  EXPECT_EQ(region.work.size(), cv::Size(640, 244));  // 488 rows halved.
  EXPECT_EQ(SearchRegionGrid(region).first_row, 480);
  std::vector<cv::Vec4f> segments = {{10, 20, 30, 41}};
  SegmentsToImage(region, &segments);
  EXPECT_EQ(segments[0], cv::Vec4f(20, 512, 60, 554));
  cv::Mat edges(240, 640, CV_8U, cv::Scalar(0));  // The region's edge map: working rows 4 on.
  edges.at<uchar>(5, 3) = 255;
  edges.at<uchar>(0, 7) = 255;
  const std::vector<Eigen::Vector2d> points = EdgePixelsInImage(region, edges);
  ASSERT_EQ(points.size(), 2u);
  EXPECT_EQ(points[0], Eigen::Vector2d(14, 480));  // Row-major order.
  EXPECT_EQ(points[1], Eigen::Vector2d(6, 490));
  // Four times too wide: halved twice, the crop 4 working rows (16 image rows) above 961,
  // rounded down to a multiple of 4.
  const cv::Mat wider(1920, 2560, CV_8UC3, cv::Scalar(90, 90, 90));
  ASSERT_TRUE(MakeJunctionSearchRegion(wider, nullptr, 961, 640, &region).ok());
  EXPECT_EQ(region.scale, 4);
  EXPECT_EQ(region.crop_top, 944);
  EXPECT_EQ(region.work_roi_top, 240 - 236);
}

TEST(JunctionSearchRegionTest, AWorkingRowLiesWhereTheMapSays) {
  // A bright image row 490: after the crop and one halving, the brightest working row maps back
  // to it (cv::pyrDown's kernel is centred on every second row).
  cv::Mat color(960, 1280, CV_8UC3, cv::Scalar(20, 20, 20));
  color.row(490).setTo(cv::Scalar(250, 250, 250));
  JunctionSearchRegion region;
  ASSERT_TRUE(MakeJunctionSearchRegion(color, nullptr, 480, 640, &region).ok());
  int brightest = -1, best = -1;
  for (int v = 0; v < region.work.rows; ++v) {
    const int value = region.work.at<cv::Vec3b>(v, 300)[0];
    if (value > best) best = value, brightest = v;
  }
  EXPECT_EQ(region.crop_top + region.scale * brightest, 490);
  // The edge map's row j is working row j + work_roi_top.
  cv::Mat edges(region.work.rows - region.work_roi_top, region.work.cols, CV_8U, cv::Scalar(0));
  edges.at<uchar>(brightest - region.work_roi_top, 150) = 255;
  EXPECT_EQ(EdgePixelsInImage(region, edges).at(0), Eigen::Vector2d(300, 490));
}

TEST(JunctionSearchRegionTest, ACallersHalvedImageIsTheWholeImage) {
  const cv::Mat color(960, 1280, CV_8UC3, cv::Scalar(90, 90, 90));
  cv::Mat halved;
  PyrDown(color, &halved);
  JunctionSearchRegion region;
  ASSERT_TRUE(MakeJunctionSearchRegion(color, &halved, 480, 640, &region).ok());
  EXPECT_EQ(region.scale, 2);
  EXPECT_EQ(region.crop_top, 0);
  EXPECT_EQ(region.work_roi_top, 240);
  EXPECT_EQ(region.work.data, halved.data);
  EXPECT_EQ(SearchRegionGrid(region).first_row, 480);  // The same rows as a crop's.
  const cv::Mat wrong_size(400, 640, CV_8UC3);
  EXPECT_EQ(MakeJunctionSearchRegion(color, &wrong_size, 480, 640, &region).code(),
            StatusCode::kInvalidArgument);
  const cv::Mat grey(480, 640, CV_8UC1);
  EXPECT_EQ(MakeJunctionSearchRegion(color, &grey, 480, 640, &region).code(),
            StatusCode::kInvalidArgument);
}

// An image that needs no halving: the caller's image must be the image itself (its size and
// type), as the header says; another one is refused, not silently ignored.
TEST(JunctionSearchRegionTest, ACallersImageIsCheckedWhenNoHalvingIsNeeded) {
  const cv::Mat color(480, 640, CV_8UC3, cv::Scalar(90, 90, 90));
  JunctionSearchRegion region;
  EXPECT_TRUE(MakeJunctionSearchRegion(color, &color, 240, 640, &region).ok());
  EXPECT_EQ(region.scale, 1);
  cv::Mat halved;
  PyrDown(color, &halved);
  EXPECT_EQ(MakeJunctionSearchRegion(color, &halved, 240, 640, &region).code(),
            StatusCode::kInvalidArgument);
}

}  // namespace
}  // namespace corridor
