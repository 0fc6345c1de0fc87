#pragma once

#include <opencv2/core.hpp>

namespace corridor {

// One channel of an 8-bit image of 2 to 4 channels as an image of its own (CV_8U, the image's
// size): the bytes cv::extractChannel gives, without cv::split's other planes. Three-channel
// images take 32 pixels a step with AVX2 where the CPU has it. An image of another depth or
// channel count, or a channel it does not have, leaves *plane empty.
void ChannelPlane(const cv::Mat& image, int channel, cv::Mat* plane);

}  // namespace corridor
