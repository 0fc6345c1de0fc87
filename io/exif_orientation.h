#pragma once

#include <string>

#include <opencv2/core.hpp>

namespace corridor {

// The EXIF orientation tag (0x0112) of a JPEG file's bytes, 1-8 as the EXIF standard numbers them
// (1 = stored upright, 6 = the camera was turned a quarter clockwise, ...); 1 when the file is
// not a JPEG, has no EXIF block or no orientation tag, or the block is malformed.
int ExifOrientation(const std::string& bytes);

// Turns an image stored with EXIF orientation `orientation` upright, as photo viewers show it.
void ApplyExifOrientation(int orientation, cv::Mat* image);

}  // namespace corridor
