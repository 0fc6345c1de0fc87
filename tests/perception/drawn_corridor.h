#pragma once

// A corridor drawn by hand with OpenCV: a floor polygon between two known junction lines that
// meet at a known vanishing point, walls of another colour, and distractors (a baseboard band
// above each junction, grout lines on the floor, a door frame). Ground truth for the detector.

#include <random>

#include <Eigen/Core>
#include <opencv2/imgproc.hpp>

namespace corridor {
namespace testing {

struct DrawnCorridor {
  cv::Mat bgr;
  Eigen::Vector2d vp;           // Vanishing point.
  Eigen::Vector2d left_point;   // A point of the left junction at the bottom row.
  Eigen::Vector2d right_point;  // A point of the right junction at the bottom row.
};

// u of the line through vp and p at row v.
inline double ColumnAt(const Eigen::Vector2d& vp, const Eigen::Vector2d& p, double v) {
  return vp.x() + (p.x() - vp.x()) * (v - vp.y()) / (p.y() - vp.y());
}

inline DrawnCorridor DrawCorridor(bool distractors, unsigned seed = 3) {
  DrawnCorridor c;
  const int w = 640, h = 480;
  c.vp = {338, 205};
  c.left_point = {40, 479};
  c.right_point = {610, 479};
  c.bgr = cv::Mat(h, w, CV_8UC3, cv::Scalar(175, 180, 185));                            // Walls.
  cv::rectangle(c.bgr, cv::Rect(0, 0, w, 150), cv::Scalar(215, 215, 215), cv::FILLED);  // Ceiling.
  const auto pt = [](const Eigen::Vector2d& p) { return cv::Point(cvRound(p.x()), cvRound(p.y())); };
  if (distractors) {
    // Baseboards: dark bands above each junction, between it and a flatter line through the VP.
    const Eigen::Vector2d left_top(c.left_point.x(), c.left_point.y() - 26);
    const Eigen::Vector2d right_top(c.right_point.x(), c.right_point.y() - 22);
    std::vector<cv::Point> left_band{pt(c.vp), pt(left_top), pt(c.left_point)};
    std::vector<cv::Point> right_band{pt(c.vp), pt(right_top), pt(c.right_point)};
    cv::fillPoly(c.bgr, std::vector<std::vector<cv::Point>>{left_band, right_band},
                 cv::Scalar(70, 70, 75), cv::LINE_AA);
    // A door frame on the right wall.
    cv::rectangle(c.bgr, cv::Rect(470, 170, 40, 250), cv::Scalar(60, 80, 120), 4);
  }
  // Floor.
  std::vector<cv::Point> floor{pt(c.vp), pt(c.left_point), cv::Point(0, h), cv::Point(w, h),
                               pt(c.right_point)};
  cv::fillPoly(c.bgr, std::vector<std::vector<cv::Point>>{floor}, cv::Scalar(80, 110, 150),
               cv::LINE_AA);
  if (distractors) {
    // Grout lines on the floor, through the VP, steeper than the junctions.
    for (double u : {200.0, 330.0, 460.0}) {
      cv::line(c.bgr, pt(c.vp), cv::Point(cvRound(u), h), cv::Scalar(60, 85, 120), 2, cv::LINE_AA);
    }
  }
  cv::Mat noise(h, w, CV_8UC3);
  cv::RNG rng(seed);
  rng.fill(noise, cv::RNG::NORMAL, 0, 3);
  c.bgr += noise;
  cv::GaussianBlur(c.bgr, c.bgr, cv::Size(3, 3), 0.8);
  return c;
}

}  // namespace testing
}  // namespace corridor
