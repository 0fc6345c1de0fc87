#include "io/exif_orientation.h"

#include <cstdint>

#include <opencv2/core.hpp>

namespace corridor {
namespace {

uint8_t Byte(const std::string& b, size_t i) { return static_cast<uint8_t>(b[i]); }

// A TIFF integer of `size` bytes at `at` in the given byte order; false past the end.
bool ReadInt(const std::string& b, size_t at, int size, bool little, uint32_t* value) {
  if (at + size > b.size()) return false;
  *value = 0;
  for (int k = 0; k < size; ++k) {
    const uint32_t byte = Byte(b, at + (little ? size - 1 - k : k));
    *value = (*value << 8) | byte;
  }
  return true;
}

// The orientation in a TIFF block (the EXIF payload after "Exif\0\0"), or 1.
int TiffOrientation(const std::string& tiff) {
  if (tiff.size() < 8) return 1;
  const bool little = tiff[0] == 'I' && tiff[1] == 'I';
  if (!little && !(tiff[0] == 'M' && tiff[1] == 'M')) return 1;
  uint32_t magic = 0, ifd = 0, count = 0;
  if (!ReadInt(tiff, 2, 2, little, &magic) || magic != 42) return 1;
  if (!ReadInt(tiff, 4, 4, little, &ifd) || !ReadInt(tiff, ifd, 2, little, &count)) return 1;
  for (uint32_t e = 0; e < count; ++e) {
    const size_t entry = ifd + 2 + 12 * static_cast<size_t>(e);
    uint32_t tag = 0, type = 0, value = 0;
    if (!ReadInt(tiff, entry, 2, little, &tag) || !ReadInt(tiff, entry + 2, 2, little, &type)) {
      return 1;
    }
    if (tag != 0x0112) continue;
    if (type != 3 || !ReadInt(tiff, entry + 8, 2, little, &value)) return 1;  // SHORT.
    return value >= 1 && value <= 8 ? static_cast<int>(value) : 1;
  }
  return 1;
}

}  // namespace

int ExifOrientation(const std::string& bytes) {
  if (bytes.size() < 4 || Byte(bytes, 0) != 0xFF || Byte(bytes, 1) != 0xD8) return 1;
  size_t i = 2;
  while (i + 4 <= bytes.size() && Byte(bytes, i) == 0xFF) {
    const uint8_t marker = Byte(bytes, i + 1);
    if (marker == 0xDA || marker == 0xD9) break;  // Image data: no EXIF block before it.
    const size_t length = (static_cast<size_t>(Byte(bytes, i + 2)) << 8) | Byte(bytes, i + 3);
    if (length < 2 || i + 2 + length > bytes.size()) break;
    if (marker == 0xE1 && length >= 8 && bytes.compare(i + 4, 6, std::string("Exif\0\0", 6)) == 0) {
      return TiffOrientation(bytes.substr(i + 10, length - 8));
    }
    i += 2 + length;
  }
  return 1;
}

void ApplyExifOrientation(int orientation, cv::Mat* image) {
  cv::Mat out;
  switch (orientation) {
    case 2:
      cv::flip(*image, out, 1);
      break;
    case 3:
      cv::rotate(*image, out, cv::ROTATE_180);
      break;
    case 4:
      cv::flip(*image, out, 0);
      break;
    case 5:
      cv::transpose(*image, out);
      break;
    case 6:
      cv::rotate(*image, out, cv::ROTATE_90_CLOCKWISE);
      break;
    case 7:
      cv::transpose(*image, out);
      cv::flip(out, out, -1);
      break;
    case 8:
      cv::rotate(*image, out, cv::ROTATE_90_COUNTERCLOCKWISE);
      break;
    default:
      return;
  }
  *image = out;
}

}  // namespace corridor
