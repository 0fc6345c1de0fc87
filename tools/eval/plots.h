#pragma once

#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "corridor_depth/status.h"
#include "corridor_depth/evaluation.h"

namespace corridor {

// AbsRel against true depth (1 m bins), one line per configuration.
cv::Mat PlotAbsRelByDepth(const std::vector<EvalReport>& configs);

// Histogram of the per-frame signed width errors (w_est - w_true) / w_true, in percent.
cv::Mat PlotWidthErrorHistogram(const EvalReport& report);

// Per-scene AbsRel, one bar per cap.
cv::Mat PlotSceneAbsRel(const EvalReport& report);

// Writes the three plots under <out_dir>/plots/ and returns their paths relative to out_dir.
Status WritePlots(const std::vector<EvalReport>& configs, const std::string& out_dir,
                  std::vector<std::string>* files);

}  // namespace corridor
