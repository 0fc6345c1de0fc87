#include "corridor_depth/image_io.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "io/exif_orientation.h"

#include "io/file_util.h"

namespace corridor {
namespace {

// Byte i of a buffer, unsigned.
uint8_t At(const std::string& b, size_t i) { return static_cast<uint8_t>(b[i]); }

bool IsPng(const std::string& b) {
  static const char kSignature[] = "\x89PNG\r\n\x1a\n";
  return b.size() >= 8 && b.compare(0, 8, kSignature, 8) == 0;
}

bool IsJpeg(const std::string& b) { return b.size() >= 3 && At(b, 0) == 0xFF && At(b, 1) == 0xD8; }

// Walks the PNG chunks (4-byte length, 4-byte type, data, 4-byte CRC) and reports whether the
// IEND chunk is present, i.e. the file was not cut short.
bool PngHasEnd(const std::string& b) {
  size_t i = 8;
  while (i + 8 <= b.size()) {
    const uint64_t length = (uint64_t{At(b, i)} << 24) | (uint64_t{At(b, i + 1)} << 16) |
                            (uint64_t{At(b, i + 2)} << 8) | uint64_t{At(b, i + 3)};
    if (b.compare(i + 4, 4, "IEND") == 0) return true;
    i += 12 + length;
  }
  return false;
}

// Walks the JPEG markers and entropy-coded scans and reports whether the end-of-image marker
// FFD9 is reached. A bare byte search could be fooled by an EXIF thumbnail's own FFD9.
bool JpegHasEnd(const std::string& b) {
  const size_t n = b.size();
  size_t i = 2;  // After SOI.
  while (i + 1 < n) {
    if (At(b, i) != 0xFF) return false;  // Lost sync: corrupt, treat as not ended.
    const uint8_t marker = At(b, i + 1);
    if (marker == 0xFF) {  // Fill byte.
      ++i;
      continue;
    }
    i += 2;
    if (marker == 0xD9) return true;
    if (marker == 0x01 || (marker >= 0xD0 && marker <= 0xD7)) continue;  // No payload.
    if (i + 2 > n) return false;
    const size_t length = (size_t{At(b, i)} << 8) | At(b, i + 1);
    if (length < 2) return false;
    i += length;
    if (marker != 0xDA) continue;
    // Scan data: FF00 is a stuffed byte and FFD0-FFD7 restart markers; anything else ends it.
    while (i + 1 < n) {
      const uint8_t next = At(b, i + 1);
      if (At(b, i) == 0xFF && next != 0x00 && !(next >= 0xD0 && next <= 0xD7)) break;
      ++i;
    }
  }
  return false;
}

// Reads and decodes a file with IMREAD_UNCHANGED; every failure is a status naming the path.
// `orientation` (may be null) receives the file's EXIF orientation (1 = upright or none).
Status DecodeFile(const std::string& path, cv::Mat* image, int* orientation = nullptr) {
  std::string bytes;
  Status status = ReadFileToString(path, &bytes);
  if (!status.ok()) return status;
  if (bytes.empty()) return Status::IoError(path + ": file is empty");
  if (IsPng(bytes) && !PngHasEnd(bytes)) {
    return Status::IoError(path + ": truncated PNG (no IEND chunk)");
  }
  if (IsJpeg(bytes) && !JpegHasEnd(bytes)) {
    return Status::IoError(path + ": truncated JPEG (no end-of-image marker FFD9)");
  }
  try {
    const cv::Mat raw(1, static_cast<int>(bytes.size()), CV_8UC1, bytes.data());
    *image = cv::imdecode(raw, cv::IMREAD_UNCHANGED);
  } catch (const cv::Exception& e) {
    return Status::IoError(path + ": cannot decode image: " + e.what());
  }
  if (image->empty()) return Status::IoError(path + ": not a readable image file");
  if (orientation != nullptr) *orientation = ExifOrientation(bytes);
  return Status::Ok();
}

}  // namespace

Status ReadColorImage(const std::string& path, cv::Mat* bgr, ImageOrientation orientation) {
  cv::Mat image;
  int exif = 1;
  Status status = DecodeFile(path, &image, &exif);
  if (!status.ok()) return status;
  if (orientation == ImageOrientation::kUpright) ApplyExifOrientation(exif, &image);
  try {
    if (image.depth() == CV_16U) {
      image.convertTo(image, CV_8U, 1.0 / 257.0);  // 65535 -> 255, rounded.
    } else if (image.depth() != CV_8U) {
      return Status::InvalidArgument(path + ": unsupported pixel type " +
                                     cv::typeToString(image.type()) +
                                     " (expected 8- or 16-bit unsigned)");
    }
    switch (image.channels()) {
      case 1:
        cv::cvtColor(image, *bgr, cv::COLOR_GRAY2BGR);
        break;
      case 2: {  // Grey + alpha: keep the grey.
        cv::Mat grey;
        cv::extractChannel(image, grey, 0);
        cv::cvtColor(grey, *bgr, cv::COLOR_GRAY2BGR);
        break;
      }
      case 3:
        *bgr = image;
        break;
      case 4:
        cv::cvtColor(image, *bgr, cv::COLOR_BGRA2BGR);
        break;
      default:
        return Status::InvalidArgument(path + ": unsupported channel count " +
                                       std::to_string(image.channels()));
    }
  } catch (const cv::Exception& e) {
    return Status::IoError(path + ": cannot convert image to BGR: " + e.what());
  }
  return Status::Ok();
}

Status ReadDepthPng(const std::string& path, cv::Mat* depth_m) {
  cv::Mat image;
  Status status = DecodeFile(path, &image);
  if (!status.ok()) return status;
  if (image.type() != CV_16UC1) {
    return Status::InvalidArgument(path +
                                   ": depth image must be 16-bit single-channel (16UC1), "
                                   "but it is " +
                                   cv::typeToString(image.type()));
  }
  image.convertTo(*depth_m, CV_32F, 0.001);  // Millimetres -> metres; 0 stays 0.
  return Status::Ok();
}

cv::Mat DepthToMillimetres(const cv::Mat& depth_m) {
  cv::Mat mm(depth_m.size(), CV_16UC1);
  for (int r = 0; r < depth_m.rows; ++r) {
    const float* src = depth_m.ptr<float>(r);
    uint16_t* dst = mm.ptr<uint16_t>(r);
    for (int c = 0; c < depth_m.cols; ++c) {
      const double v = src[c];
      // Non-finite and non-positive depths are "no depth"; the rest rounds to the nearest mm.
      const double rounded = (std::isfinite(v) && v > 0) ? std::round(v * 1000.0) : 0.0;
      dst[c] = static_cast<uint16_t>(rounded > 65535.0 ? 65535.0 : rounded);
    }
  }
  return mm;
}

Status WriteDepthPng(const std::string& path, const cv::Mat& depth_m) {
  if (depth_m.empty()) return Status::InvalidArgument(path + ": depth image to write is empty");
  if (depth_m.type() != CV_32FC1) {
    return Status::InvalidArgument(path + ": depth to write must be 32FC1 metres, but it is " +
                                   cv::typeToString(depth_m.type()));
  }
  if (LowerExtension(path) != ".png") {
    return Status::InvalidArgument(path + ": depth images must be written as .png");
  }
  return WriteImageAtomic(path, DepthToMillimetres(depth_m));
}

Status WriteImageAtomic(const std::string& path, const cv::Mat& image) {
  if (image.empty()) return Status::InvalidArgument(path + ": image to write is empty");
  bool has_writer = false;
  try {
    has_writer = cv::haveImageWriter(path);
  } catch (const cv::Exception&) {
  }
  if (!has_writer) {
    return Status::InvalidArgument(path + ": no image encoder for extension '" +
                                   LowerExtension(path) + "'");
  }
  std::string tmp;
  Status status = PrepareAtomicWrite(path, &tmp);
  if (!status.ok()) return status;
  bool written = false;
  std::string reason = "encoder failed";
  try {
    written = cv::imwrite(tmp, image);
  } catch (const cv::Exception& e) {
    reason = e.what();
  }
  if (!written) {
    std::remove(tmp.c_str());
    return Status::IoError(path + ": cannot write image (" + reason + ")");
  }
  return FinishAtomicWrite(tmp, path);
}

Status WriteTextAtomic(const std::string& path, const std::string& text) {
  std::string tmp;
  Status status = PrepareAtomicWrite(path, &tmp);
  if (!status.ok()) return status;
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out << text;
    out.close();
    if (!out) {
      std::remove(tmp.c_str());
      return Status::IoError(path + ": cannot write " + tmp);
    }
  }
  return FinishAtomicWrite(tmp, path);
}

}  // namespace corridor
