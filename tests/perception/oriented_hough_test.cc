// OrientedHoughSegments: the sides of a drawn polygon are found where the polygon's vertices say
// they are; an edge pixel's vote follows its gradient; no call leaks into the next.

#include "kernels/oriented_hough.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Geometry>
#include <opencv2/imgproc.hpp>

namespace corridor {
namespace {

struct EdgeInput {
  cv::Mat edges, dx, dy;
};

// Sobel gradients and Canny edges of a grey image, as the junction detector makes them.
EdgeInput EdgesOf(const cv::Mat& grey) {
  EdgeInput in;
  cv::Sobel(grey, in.dx, CV_16S, 1, 0, 3);
  cv::Sobel(grey, in.dy, CV_16S, 0, 1, 3);
  cv::Canny(in.dx, in.dy, in.edges, 40, 100, false);
  return in;
}

// A dark quadrilateral on a light background: four sides at different angles.
const std::vector<cv::Point> kQuad = {{40, 200}, {150, 40}, {290, 90}, {250, 220}};

cv::Mat QuadImage(int width = 320, int height = 240) {
  cv::Mat grey(height, width, CV_8U, cv::Scalar(200));
  cv::fillConvexPoly(grey, kQuad, cv::Scalar(60), cv::LINE_8);
  return grey;
}

// Fraction of the side a -> b covered by segments lying along it (both ends within `distance`).
double Covered(const std::vector<cv::Vec4i>& segments, const cv::Point& a, const cv::Point& b,
               double distance) {
  const Eigen::Vector2d pa(a.x, a.y), pb(b.x, b.y);
  const double length = (pb - pa).norm();
  const Eigen::Vector2d along = (pb - pa) / length;
  const Eigen::Vector2d normal(-along.y(), along.x());
  std::vector<int> hit(static_cast<size_t>(length) + 1, 0);
  for (const cv::Vec4i& s : segments) {
    const Eigen::Vector2d p(s[0], s[1]), q(s[2], s[3]);
    if (std::abs((p - pa).dot(normal)) > distance || std::abs((q - pa).dot(normal)) > distance) {
      continue;
    }
    double t0 = (p - pa).dot(along), t1 = (q - pa).dot(along);
    if (t0 > t1) std::swap(t0, t1);
    for (int t = std::max(0, static_cast<int>(std::ceil(t0)));
         t <= std::min(static_cast<int>(length), static_cast<int>(t1)); ++t) {
      hit[static_cast<size_t>(t)] = 1;
    }
  }
  int sum = 0;
  for (int h : hit) sum += h;
  return static_cast<double>(sum) / hit.size();
}

TEST(OrientedHoughTest, FindsEverySideOfADrawnQuadrilateralWhereItsCornersSay) {
  const EdgeInput in = EdgesOf(QuadImage());
  std::vector<cv::Vec4i> segments;
  OrientedHoughOptions options;
  options.min_length = 10;
  OrientedHoughSegments(in.edges, in.dx, in.dy, options, &segments);
  ASSERT_FALSE(segments.empty());
  for (size_t i = 0; i < kQuad.size(); ++i) {
    const cv::Point& a = kQuad[i];
    const cv::Point& b = kQuad[(i + 1) % kQuad.size()];
    // The corners themselves round off in Canny; the sides' middles must be there.
    EXPECT_GT(Covered(segments, a, b, 2.0), 0.8) << "side " << i;
  }
  // And nothing else: every segment lies on one of the sides.
  for (const cv::Vec4i& s : segments) {
    bool on_a_side = false;
    for (size_t i = 0; i < kQuad.size() && !on_a_side; ++i) {
      on_a_side = Covered({s}, kQuad[i], kQuad[(i + 1) % kQuad.size()], 2.5) > 0;
    }
    EXPECT_TRUE(on_a_side) << s;
  }
}

// A row of edge pixels is a horizontal line; whether it is found depends on what the gradients
// say about its pixels, not on the pixels alone (cv::HoughLinesP, which ignores gradients, finds
// it either way: the premise).
TEST(OrientedHoughTest, EdgePixelsVoteOnlyForLinesAlongTheirGradient) {
  cv::Mat edges(120, 240, CV_8U, cv::Scalar(0));
  edges.row(50).colRange(20, 220).setTo(cv::Scalar(255));
  std::vector<cv::Vec4i> reference;
  cv::HoughLinesP(edges, reference, 1, CV_PI / 180, 25, 10, 6);
  ASSERT_FALSE(reference.empty());
  OrientedHoughOptions options;
  options.min_length = 10;
  std::vector<cv::Vec4i> segments;
  // Gradient across the row (a horizontal edge): one segment along it.
  cv::Mat dx(edges.size(), CV_16S, cv::Scalar(0)), dy(edges.size(), CV_16S, cv::Scalar(200));
  OrientedHoughSegments(edges, dx, dy, options, &segments);
  ASSERT_EQ(segments.size(), 1u);
  EXPECT_EQ(std::min(segments[0][0], segments[0][2]), 20);
  EXPECT_EQ(std::max(segments[0][0], segments[0][2]), 219);
  EXPECT_EQ(segments[0][1], 50);
  EXPECT_EQ(segments[0][3], 50);
  // Gradient along the row (each pixel says "a vertical edge"): 90 degrees off, no line.
  dx.setTo(cv::Scalar(200));
  dy.setTo(cv::Scalar(0));
  OrientedHoughSegments(edges, dx, dy, options, &segments);
  EXPECT_TRUE(segments.empty());
  // 10 degrees off, inside the default 15 degree window: found again.
  dx.setTo(cv::Scalar(static_cast<int>(std::lround(200 * std::sin(10 * M_PI / 180)))));
  dy.setTo(cv::Scalar(static_cast<int>(std::lround(200 * std::cos(10 * M_PI / 180)))));
  OrientedHoughSegments(edges, dx, dy, options, &segments);
  EXPECT_EQ(segments.size(), 1u);
}

// The accumulator keeps, per angle, only the rhos the map's pixels reach there (their extremes are
// at its corners). The map's own borders are lines at those extremes: a row too short would put
// their votes in another angle's bins. Each border is found whole, on maps of several shapes.
TEST(OrientedHoughTest, LinesAlongTheMapsBordersAreFoundWhole) {
  for (const cv::Size size : {cv::Size(97, 41), cv::Size(41, 97), cv::Size(320, 240)}) {
    const int w = size.width, h = size.height;
    cv::Mat edges(size, CV_8U, cv::Scalar(0));
    cv::Mat dx(size, CV_16S, cv::Scalar(0)), dy(size, CV_16S, cv::Scalar(0));
    // Gradients across each border (the corners keep the last one written).
    edges.row(0).setTo(255);
    dy.row(0).setTo(200);
    edges.row(h - 1).setTo(255);
    dy.row(h - 1).setTo(-200);
    edges.col(0).setTo(255);
    dx.col(0).setTo(200);
    dy.col(0).setTo(0);
    edges.col(w - 1).setTo(255);
    dx.col(w - 1).setTo(-200);
    dy.col(w - 1).setTo(0);
    OrientedHoughOptions options;
    options.min_length = 10;
    std::vector<cv::Vec4i> segments;
    OrientedHoughSegments(edges, dx, dy, options, &segments);
    const cv::Point corners[4] = {{0, 0}, {w - 1, 0}, {w - 1, h - 1}, {0, h - 1}};
    for (int i = 0; i < 4; ++i) {
      EXPECT_GT(Covered(segments, corners[i], corners[(i + 1) % 4], 0.5), 0.9)
          << w << "x" << h << ", border " << i;
    }
  }
}

// The accumulator is reused by the calls of a thread: each call must leave it empty.
TEST(OrientedHoughTest, TheSameImageGivesTheSameSegmentsWhateverCameBefore) {
  const EdgeInput quad = EdgesOf(QuadImage());
  cv::Mat other_grey(240, 320, CV_8U, cv::Scalar(30));
  cv::circle(other_grey, {160, 120}, 70, cv::Scalar(220), cv::FILLED);
  cv::rectangle(other_grey, {20, 20}, {120, 90}, cv::Scalar(120), cv::FILLED);
  const EdgeInput other = EdgesOf(other_grey);
  const EdgeInput small = EdgesOf(QuadImage(300, 230));  // Another accumulator size.
  OrientedHoughOptions options;
  std::vector<cv::Vec4i> first, again;
  OrientedHoughSegments(quad.edges, quad.dx, quad.dy, options, &first);
  for (const EdgeInput* before : {&other, &quad, &small, &other}) {
    std::vector<cv::Vec4i> ignored;
    OrientedHoughSegments(before->edges, before->dx, before->dy, options, &ignored);
    OrientedHoughSegments(quad.edges, quad.dx, quad.dy, options, &again);
    ASSERT_EQ(again.size(), first.size());
    for (size_t i = 0; i < first.size(); ++i) EXPECT_EQ(again[i], first[i]) << i;
  }
}

// The draw order is fixed by each pixel's coordinates: one edge pixel more, away from every line,
// leaves every segment as it was. (Drawn from a pool by a random number generator, every later
// pixel's turn would change, and with it segments all over a cluttered image.)
TEST(OrientedHoughTest, OneMoreEdgePixelLeavesTheOtherSegmentsAsTheyWere) {
  // Clutter: forty short dark strokes at random angles over the quadrilateral.
  cv::Mat grey = QuadImage();
  cv::RNG rng(5);
  for (int i = 0; i < 40; ++i) {
    const cv::Point a(rng.uniform(0, 320), rng.uniform(0, 240));
    const double angle = rng.uniform(0.0, M_PI);
    const int length = rng.uniform(15, 60);
    const cv::Point b(a.x + static_cast<int>(length * std::cos(angle)),
                      a.y + static_cast<int>(length * std::sin(angle)));
    cv::line(grey, a, b, cv::Scalar(rng.uniform(0, 120)), 2);
  }
  const EdgeInput in = EdgesOf(grey);
  OrientedHoughOptions options;
  options.threshold = 15;
  std::vector<cv::Vec4i> before;
  OrientedHoughSegments(in.edges, in.dx, in.dy, options, &before);
  ASSERT_GT(before.size(), 20u) << "premise: a cluttered image";
  const auto sorted = [](std::vector<cv::Vec4i> s) {
    std::sort(s.begin(), s.end(), [](const cv::Vec4i& a, const cv::Vec4i& b) {
      return std::lexicographical_compare(&a[0], &a[0] + 4, &b[0], &b[0] + 4);
    });
    return s;
  };
  int tried = 0;
  for (int k = 0; k < 200 && tried < 5; ++k) {
    const cv::Point p(rng.uniform(2, 318), rng.uniform(2, 238));
    if (cv::countNonZero(in.edges(cv::Rect(p.x - 2, p.y - 2, 5, 5))) > 0) continue;  // Near one.
    ++tried;
    EdgeInput more{in.edges.clone(), in.dx.clone(), in.dy.clone()};
    more.edges.at<uchar>(p) = 255;
    more.dx.at<short>(p) = 200;  // A vertical edge's gradient.
    more.dy.at<short>(p) = 0;
    std::vector<cv::Vec4i> after;
    OrientedHoughSegments(more.edges, more.dx, more.dy, options, &after);
    EXPECT_EQ(sorted(after), sorted(before)) << "one more edge pixel at " << p;
  }
  EXPECT_EQ(tried, 5);
}

TEST(OrientedHoughTest, InputsThatDoNotMatchGiveNoSegments) {
  const EdgeInput in = EdgesOf(QuadImage());
  const OrientedHoughOptions options;
  std::vector<cv::Vec4i> segments = {cv::Vec4i(1, 2, 3, 4)};
  OrientedHoughSegments(cv::Mat(), in.dx, in.dy, options, &segments);
  EXPECT_TRUE(segments.empty());
  cv::Mat dx32;
  in.dx.convertTo(dx32, CV_32F);
  OrientedHoughSegments(in.edges, dx32, in.dy, options, &segments);
  EXPECT_TRUE(segments.empty());
  OrientedHoughSegments(in.edges, in.dx.colRange(0, 100), in.dy, options, &segments);
  EXPECT_TRUE(segments.empty());
  cv::Mat edges16;
  in.edges.convertTo(edges16, CV_16U);
  OrientedHoughSegments(edges16, in.dx, in.dy, options, &segments);
  EXPECT_TRUE(segments.empty());
}

// A fuzzer finding: a gap of 1e300 px was converted to int (undefined). Absurd options are
// clamped: any gap at least the image's size bridges everything (as an image-sized one does),
// NaN counts as none, and windows beyond 89 degrees mean all angles.
TEST(OrientedHoughTest, AbsurdOptionsAreClampedNotConverted) {
  const EdgeInput in = EdgesOf(QuadImage());
  OrientedHoughOptions image_sized, huge, nan_gap, no_gap;
  image_sized.max_gap = 320 + 240;
  huge.max_gap = 1e300;
  nan_gap.max_gap = std::nan("");
  no_gap.max_gap = 0;
  std::vector<cv::Vec4i> expected, got;
  OrientedHoughSegments(in.edges, in.dx, in.dy, image_sized, &expected);
  OrientedHoughSegments(in.edges, in.dx, in.dy, huge, &got);
  EXPECT_EQ(got, expected);
  OrientedHoughSegments(in.edges, in.dx, in.dy, no_gap, &expected);
  OrientedHoughSegments(in.edges, in.dx, in.dy, nan_gap, &got);
  EXPECT_EQ(got, expected);
  OrientedHoughOptions wide, widest;
  wide.angle_window_deg = 1e300;
  widest.angle_window_deg = 89;
  OrientedHoughSegments(in.edges, in.dx, in.dy, widest, &expected);
  OrientedHoughSegments(in.edges, in.dx, in.dy, wide, &got);
  EXPECT_EQ(got, expected);
  EXPECT_FALSE(got.empty());
}

}  // namespace
}  // namespace corridor
