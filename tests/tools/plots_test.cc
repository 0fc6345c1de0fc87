#include "tools/eval/plots.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <opencv2/imgcodecs.hpp>

#include "tests/evaluation/eval_test_records.h"

namespace corridor {
namespace {

using testing_util::Frames;

// Pixels that are not white.
int Ink(const cv::Mat& image) {
  cv::Mat grey;
  cv::extractChannel(image, grey, 0);
  return cv::countNonZero(grey < 250);
}

TEST(Plots, EachPlotDrawsSomething) {
  const EvalReport r = BuildReport(Frames(), {1.5, 2.0}, "grid", "paper");
  for (const cv::Mat& image :
       {PlotAbsRelByDepth({r}), PlotWidthErrorHistogram(r), PlotSceneAbsRel(r)}) {
    ASSERT_FALSE(image.empty());
    EXPECT_EQ(image.type(), CV_8UC3);
    EXPECT_GT(Ink(image), 1000);
  }
  const EvalReport empty = BuildReport({}, {5.0}, "grid", "paper");
  EXPECT_FALSE(PlotAbsRelByDepth({empty}).empty());
  EXPECT_FALSE(PlotWidthErrorHistogram(empty).empty());
  EXPECT_FALSE(PlotSceneAbsRel(empty).empty());
}

TEST(Plots, WritesPngsUnderPlots) {
  const std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) /
                                    ("corridor_plots_" + std::to_string(::getpid()));
  std::vector<std::string> files;
  ASSERT_TRUE(
      WritePlots({BuildReport(Frames(), {1.5, 2.0}, "grid", "paper")}, dir.string(), &files).ok());
  ASSERT_EQ(files.size(), 3u);
  for (const auto& f : files) {
    EXPECT_EQ(f.rfind("plots/", 0), 0u);
    EXPECT_FALSE(cv::imread((dir / f).string()).empty()) << f;
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace corridor
