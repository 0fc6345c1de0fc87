#pragma once

#include <opencv2/core.hpp>
#include <string>

#include "corridor_depth/recover_depth.h"

namespace corridor {

// The colour scales of an evaluation picture.
struct EvalPanelScales {
  double max_depth = 15.0;  // Top of the scale shared by the predicted and true depth, m.
  double max_error = 1.0;   // Top of the absolute error scale, m.
};

// |pred - gt| (CV_32F metres) where both are > 0, and 0 elsewhere.
cv::Mat AbsoluteErrorMap(const cv::Mat& pred, const cv::Mat& gt);

// A vertical colour bar for the error map's scale (inferno), labelled in metres.
cv::Mat ErrorColorBar(int height, double max_error);

// One row: input with lines | predicted depth | ground truth | depth colour bar | absolute error
// | error colour bar, each panel titled. `gt` may be empty (no ground truth); `pred` may be
// empty (the frame failed). `caption` is written over the input panel (wrapped; '\n' breaks).
cv::Mat MakeEvalPanel(const cv::Mat& bgr, const RecoverDepthResult& result, const cv::Mat& pred,
                      const cv::Mat& gt, const EvalPanelScales& scales, const std::string& caption);

}  // namespace corridor
