#include "evaluation/frame_panel.h"

#include <gtest/gtest.h>

namespace corridor {
namespace {

TEST(AbsoluteErrorMap, OnlyWhereBothExist) {
  const cv::Mat gt = (cv::Mat_<float>(1, 4) << 2.0f, 3.0f, 0.0f, 4.0f);
  const cv::Mat pred = (cv::Mat_<float>(1, 4) << 2.5f, 0.0f, 1.0f, 3.0f);
  const cv::Mat error = AbsoluteErrorMap(pred, gt);
  ASSERT_EQ(error.type(), CV_32F);
  EXPECT_FLOAT_EQ(error.at<float>(0, 0), 0.5f);
  EXPECT_FLOAT_EQ(error.at<float>(0, 1), 0.0f);
  EXPECT_FLOAT_EQ(error.at<float>(0, 2), 0.0f);
  EXPECT_FLOAT_EQ(error.at<float>(0, 3), 1.0f);
  EXPECT_EQ(cv::countNonZero(AbsoluteErrorMap(cv::Mat(), gt)), 0);  // Mismatch: nothing.
}

TEST(ErrorColorBar, SizeAndColours) {
  const cv::Mat bar = ErrorColorBar(100, 0.5);
  EXPECT_EQ(bar.rows, 100);
  EXPECT_EQ(bar.type(), CV_8UC3);
  // Inferno: bright yellow on top (large error), near black at the bottom.
  const cv::Vec3b top = bar.at<cv::Vec3b>(0, 2), bottom = bar.at<cv::Vec3b>(99, 2);
  EXPECT_GT(top[1] + top[2], bottom[1] + bottom[2] + 200);
}

TEST(MakeEvalPanel, PanelsSideBySide) {
  const cv::Mat bgr(60, 80, CV_8UC3, cv::Scalar(100, 100, 100));
  cv::Mat gt(60, 80, CV_32F, cv::Scalar(4.0f));
  cv::Mat pred(60, 80, CV_32F, cv::Scalar(4.5f));
  pred(cv::Rect(0, 0, 80, 30)).setTo(0);
  RecoverDepthResult result;
  result.junctions.status = Status::NoCorridorFound("test");
  const cv::Mat panel = MakeEvalPanel(bgr, result, pred, gt, EvalPanelScales(), "caption");
  EXPECT_GT(panel.cols, 4 * 80);
  EXPECT_GT(panel.rows, 60);  // Title strips.
  // Failed frame, no ground truth: still one picture, same layout.
  const cv::Mat failed = MakeEvalPanel(bgr, result, cv::Mat(), cv::Mat(), EvalPanelScales(), "x");
  EXPECT_EQ(failed.size(), panel.size());
}

}  // namespace
}  // namespace corridor
